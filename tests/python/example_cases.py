"""The bundled example cases for the Python tests (DYNCONTACT_SOURCE_DIR: the source tree)."""
import json
import os

SOURCE = os.environ.get("DYNCONTACT_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def example(name):
    """examples/NAME.json as a dict."""
    with open(os.path.join(SOURCE, "examples", name + ".json")) as f:
        return json.load(f)
