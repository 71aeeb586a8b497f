#!/usr/bin/env bash
# wineserver.sh start|stop BUILD: the windows label's persistent wineserver, in the build tree's own
# prefix. start makes the prefix once (wineboot), starts `wineserver -p` (persistent: it stays when
# the last program ends, so each .exe starts in hundredths of a second, not half a second) and keeps
# its PID in BUILD/wine.pid; stop ends that PID and nothing else.
set -euo pipefail
action="$1" build="$2"
export WINEPREFIX="$build/wine" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
pidfile="$build/wine.pid"
case "$action" in
  start)
    if [ -f "$pidfile" ] && kill -0 "$(cat "$pidfile")" 2>/dev/null; then exit 0; fi
    mkdir -p "$WINEPREFIX"
    wineserver -p &
    echo $! >"$pidfile"
    # The first start makes the prefix (a minute on a busy machine); later ones find it.
    [ -f "$WINEPREFIX/system.reg" ] || wineboot -i >/dev/null 2>&1 || true
    wine cmd /c exit 0 >/dev/null 2>&1
    echo "wineserver $(cat "$pidfile") serving $WINEPREFIX"
    ;;
  stop)
    [ -f "$pidfile" ] || exit 0
    pid="$(cat "$pidfile")"
    rm -f "$pidfile"
    kill "$pid" 2>/dev/null || true
    ;;
  *) echo "usage: wineserver.sh start|stop BUILD" >&2; exit 2 ;;
esac
