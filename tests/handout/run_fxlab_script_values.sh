#!/usr/bin/env bash
# ./fxlab handout with an option that takes a value given last without one: a message naming the
# option and exit code 2, before anything is installed or built (issue 40: exit 1 and no word).
#   run_fxlab_script_values.sh <the fxlab script>
set -uo pipefail
script="$1"
status=0
for args in "01 --out" "--lang" "01 --bench-dir" "01 --size" "01 --frames"; do
  # shellcheck disable=SC2086
  message=$(bash "$script" handout $args 2>&1 </dev/null)
  code=$?
  option=${args##* }
  if [ "$code" -ne 2 ] || ! grep -q "fxlab handout: $option needs a value" <<<"$message"; then
    echo "FAIL: ./fxlab handout $args: exit $code, said: $message"
    status=1
  else
    echo "ok: ./fxlab handout $args: $message"
  fi
done
exit "$status"
