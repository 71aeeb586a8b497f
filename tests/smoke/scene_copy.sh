# Sourced by the smoke scripts that run a lesson on edited copies of its shipped scene.
# Expects $shipped (the scene file copied) and $status (the script's exit status) to be set.

# fail <message>: report a failed check; the script goes on and exits with status 1.
fail() { echo "FAIL: $*"; status=1; }

# edit <out file> <python statements on the dict d>: a copy of $shipped with d changed.
edit() {
  python3 - "$shipped" "$1" "$2" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
exec(sys.argv[3])
json.dump(d, open(sys.argv[2], "w"), indent=2)
PY
}
