"""scripts/install_python_module.sh (run by scripts/setup.sh): `python3 -c "import dyncontact"`
works for another interpreter of the same Python version first on PATH (here a virtual
environment without NumPy, as pyenv's python3 next to Debian's)."""
import os
import shutil
import subprocess
import sys

import pytest

import dyncontact

from example_cases import SOURCE


def test_install_script_makes_python3_on_path_import_the_module(tmp_path):
    build_dir = os.path.dirname(os.path.dirname(os.path.abspath(dyncontact.__file__)))
    if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
        pytest.skip("the module is not in a build folder")
    venv = tmp_path / "venv"
    made = subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(venv)], capture_output=True, text=True)
    if made.returncode != 0:
        pytest.skip("no venv here: " + made.stderr)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    env["PATH"] = str(venv / "bin") + os.pathsep + env.get("PATH", "")
    check = [str(venv / "bin" / "python3"), "-c", "import dyncontact, numpy; print(dyncontact.__file__)"]
    assert subprocess.run(check, env=env, capture_output=True, cwd=tmp_path).returncode != 0  # not there yet
    script = os.path.join(SOURCE, "scripts", "install_python_module.sh")
    r = subprocess.run(["bash", script, build_dir], env=env, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert "installed the Python module" in r.stderr
    assert "fails" not in r.stderr, r.stderr
    got = subprocess.run(check, env=env, capture_output=True, text=True, cwd=tmp_path)
    assert got.returncode == 0, got.stderr
    assert got.stdout.startswith(str(venv))
    shutil.rmtree(venv)
