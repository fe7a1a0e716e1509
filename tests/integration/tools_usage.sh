#!/bin/bash
# Every tools/*.py, given no arguments or a wrong one by the python3 first on PATH (which may lack h5py, e.g. a
# pyenv or conda python), prints a usage or error line and exits 2, never a traceback.
# Usage: tools_usage.sh SOURCE_DIR
set -u
src=$1
status=0
for tool in "$src"/tools/*.py; do
  [ "$(basename "$tool")" = debian_python.py ] && continue
  for args in "" "/no/such/dir" "--help"; do
    err=$(python3 "$tool" $args 2>&1 >/dev/null)
    code=$?
    if [ $code -ne 2 ] || [ -z "$err" ] || grep -q Traceback <<<"$err"; then
      echo "FAIL: python3 $tool $args -> exit $code: $err"
      status=1
    fi
  done
done
[ $status -eq 0 ] && echo "every tool prints its usage or an error line with exit 2"
exit $status
