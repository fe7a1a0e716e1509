#!/usr/bin/env bash
# Checks that a refactor leaves results unchanged: every shipped case (and the variants a campaign uses) run for a
# short strain by two binaries, same seed, and compared bit for bit (tools/compare_runs.py). The pairwise engine
# must agree exactly; FCM runs differ run to run at ~1e-12 by themselves (FFTW_MEASURE plans), so a FCM case is
# also run twice by the old binary to show that noise level.
# usage: tools/refactor_check.sh OLD_SUSPEND NEW_SUSPEND OUT_DIR [STRAIN (default 0.05)] [CASE NAMES (default all)]
# NEW_SETS="key=value ...": assignments for the new binary only, e.g. the former defaults of keys whose default
# changed (NEW_SETS="run.time_step.bound=particles run.time_step.contacts=explicit"), so what remains is the refactor.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
old=$1 new=$2 out=$3 strain=${4:-0.05}
only=${5:-}
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive HDF5_USE_FILE_LOCKING=FALSE
v=$root/cases/validation
# name | case | extra --set assignments (the 65536-sphere cases run at 4096 spheres)
cases=(
  "adhesive_hertz|$v/adhesive_hertz.yaml|"
  "adhesive_hertz_mu0|$v/adhesive_hertz.yaml|contact.mu_s=0"
  "critical_load|$v/critical_load_thickening.yaml|"
  "crossval_adhesive|$v/crossval_adhesive.yaml|"
  "crossval_dilute|$v/crossval_dilute.yaml|"
  "crossval_frictional|$v/crossval_frictional.yaml|"
  "pair_squeeze|$v/crossval_pair_squeeze.yaml|"
  "frictional_mu1|$v/frictional_mu1.yaml|"
  "frictionless_jamming|$v/frictionless_jamming.yaml|"
  "bidisperse_uniform|$v/large_bidisperse_uniform.yaml|particles.count=4096"
  "bidisperse_wavy|$v/large_bidisperse_wavy.yaml|particles.count=4096"
  "repulsion_vdw|$v/repulsion_vdw_rate_sweep.yaml|"
  "quickstart|$root/cases/quickstart.yaml|"
  "phim_stress|$root/cases/phim/adhesive_bidisperse.yaml|flow.shear_stress=2"
  "phim_stress_mu0|$root/cases/phim/adhesive_bidisperse.yaml|flow.shear_stress=2 contact.mu_s=0"
  "oscillatory|$root/cases/protocols/oscillatory_frictional.yaml|"
  "fcm_adhesive|$v/crossval_adhesive.yaml|hydrodynamics.model=fcm"
  "jkr_pull_off|$v/jkr_pull_off.yaml|"
  "damped_rolling|$v/frictional_mu1.yaml|contact.gamma_n=0.04 contact.rolling.mu_r=0.1"
)
mkdir -p "$out"
status=0
for entry in "${cases[@]}"; do
  IFS='|' read -r name file sets <<< "$entry"
  [[ -n $only && " $only " != *" $name "* ]] && continue
  args=(--set "run.strain=$strain" --set run.average_from=0)
  for s in $sets; do args+=(--set "$s"); done
  runs=(old new)
  [[ $sets == *fcm* ]] && runs+=(old2)
  for r in "${runs[@]}"; do
    bin=$old; extra=()
    if [[ $r == new ]]; then
      bin=$new
      for s in ${NEW_SETS:-}; do extra+=(--set "$s"); done
    fi
    rm -rf "${out:?}/$name.$r"
    "$bin" run "$file" "${args[@]}" "${extra[@]}" --out "$out/$name.$r" --quiet > "$out/$name.$r.log" 2>&1 || { echo "$name: $r run failed (see $out/$name.$r.log)"; status=1; }
  done
  printf "%-22s new vs old: " "$name"
  /usr/bin/python3 "$root/tools/compare_runs.py" "$out/$name.old" "$out/$name.new" | head -4 || status=1
  if [[ -d $out/$name.old2 ]]; then
    printf "%-22s old vs old: " "$name"
    /usr/bin/python3 "$root/tools/compare_runs.py" "$out/$name.old" "$out/$name.old2" | head -1 || true
  fi
done
exit $status
