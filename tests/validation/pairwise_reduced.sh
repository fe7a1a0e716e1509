#!/bin/bash
# Reduced pairwise validation for CI (ctest label `validation`): the published cases at small N and short strain.
# Full-size runs and their acceptance: the case headers and tools/validate_pairwise.py. Usage: pairwise_reduced.sh SUSPEND SOURCE_DIR
set -euo pipefail
suspend=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() { out=$work/$1; shift; "$suspend" run "$@" --out "$out" --threads 1 --quiet > "$out.log"; }
small="--set particles.count=200 --set run.strain=3 --set run.average_from=1"
run fl45 "$src/cases/validation/frictionless_jamming.yaml" $small --set particles.phi=0.45
run fl55 "$src/cases/validation/frictionless_jamming.yaml" $small --set particles.phi=0.55
run fr45 "$src/cases/validation/frictional_mu1.yaml" $small --set particles.phi=0.45
# Critical-load thickening at phi = 0.56: frictionless at the low rate, frictional (stiffer springs) at the high one.
thick="--set particles.count=200 --set run.strain=1.5 --set run.average_from=0.5"
run cl_low "$src/cases/validation/critical_load_thickening.yaml" $thick --set contact.critical_load=1885
run cl_high "$src/cases/validation/critical_load_thickening.yaml" $thick --set contact.critical_load=0.1885 \
  --set contact.k_hat=1e7
check=$src/tools/validate_pairwise.py
python3 "$check" frictionless "$work/fl45" "$work/fl55" --tolerance 0.3
python3 "$check" frictional "$work/fr45" --tolerance 0.35
python3 "$check" thickening "$work/cl_low" "$work/cl_high" --factor 3
# Signs of the normal stresses and of their contact and lubrication parts (docs/validation.md section 4).
python3 "$check" normal_stress frictionless "$work/fl45" "$work/fl55"
python3 "$check" normal_stress frictional "$work/fr45"
