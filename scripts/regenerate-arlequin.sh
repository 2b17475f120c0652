#!/usr/bin/env bash
# Regenerates the shipped Arlequin weights, data/arlequin/<module>.json, with EvoStick's
# shipped seed and generations (the defaults of `swarmdesign evostick --module`), then
# rebuilds so the binary carries them. The result does not depend on the thread count; git
# diff data/arlequin shows whether anything changed (it must not, unless the simulator,
# the reference model, the network or EvoStick changed). Prints each module's wall time.
# Usage: scripts/regenerate-arlequin.sh [THREADS]   (default: all cores)
set -euo pipefail
cd "$(dirname "$0")/.."
threads="${1:-0}"
cmake --build build --target swarmdesign
start=$(date +%s)
for module in exploration stop phototaxis antiphototaxis attraction repulsion; do
  t0=$(date +%s)
  ./build/swarmdesign evostick --module "$module" --threads "$threads" --output "data/arlequin/$module.json" >/dev/null
  echo "$module: $(($(date +%s) - t0)) s"
done
echo "all six: $(($(date +%s) - start)) s"
cmake --build build --target swarmdesign
