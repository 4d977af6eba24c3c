#!/usr/bin/env bash
# Draws docs/figures/architecture.svg from its text source docs/figures/architecture.dot with
# Graphviz's dot (Debian: apt-get install graphviz). The SVG is committed; run this after
# editing the .dot file.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
command -v dot >/dev/null || { echo "make_architecture_figure: dot not found (apt-get install graphviz)" >&2; exit 1; }
dot -Tsvg docs/figures/architecture.dot -o docs/figures/architecture.svg.tmp
mv docs/figures/architecture.svg.tmp docs/figures/architecture.svg
echo "docs/figures/architecture.svg"
