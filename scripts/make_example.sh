#!/usr/bin/env bash
# Generates the bundled example: a small synthetic scene of KIT's FZK-Haus (CityGML 2.0, LoD3).
set -euo pipefail
cd "$(dirname "$0")/.."
echo "make_example: the synthetic scene generator is not built yet (issue 3, part 5)"
