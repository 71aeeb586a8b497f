#!/usr/bin/env bash
# wineserver.sh start|stop BUILD: the windows label's persistent wineserver, in the build tree's own
# prefix. start makes the prefix once (wineboot), starts `wineserver -p` (persistent: it stays when
# the last program ends, so each .exe starts in hundredths of a second, not half a second) and keeps
# its PID in BUILD/wine.pid; stop ends this prefix's Wine processes and that PID, nothing else.
set -euo pipefail
action="$1" build="$(cd "$2" && pwd)"
export WINEPREFIX="$build/wine" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
pidfile="$build/wine.pid"
case "$action" in
  start)
    if [ -f "$pidfile" ] && kill -0 "$(cat "$pidfile")" 2>/dev/null; then exit 0; fi
    mkdir -p "$WINEPREFIX"
    # -f: in the foreground, so that $! is the server itself (a daemon would leave another PID); its
    # output goes to a log, so that it holds no pipe of the test that started it.
    wineserver -f -p >"$build/wineserver.log" 2>&1 </dev/null &
    echo $! >"$pidfile"
    # The first start makes the prefix (a minute on a busy machine); later ones find it.
    [ -f "$WINEPREFIX/system.reg" ] || wineboot -i >/dev/null 2>&1 </dev/null || true
    wine cmd /c exit 0 >/dev/null 2>&1 </dev/null
    echo "wineserver $(cat "$pidfile") serving $WINEPREFIX"
    ;;
  stop)
    [ -f "$pidfile" ] || exit 0
    pid="$(cat "$pidfile")"
    rm -f "$pidfile"
    # The prefix's own service processes (services.exe, winedevice.exe, ...) outlive a server that is
    # simply killed: the server ends them first (-k acts on this prefix only), then our PID.
    wineserver -k >/dev/null 2>&1 || true
    kill "$pid" 2>/dev/null || true
    ;;
  *) echo "usage: wineserver.sh start|stop BUILD" >&2; exit 2 ;;
esac
