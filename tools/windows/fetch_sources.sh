#!/usr/bin/env bash
# Fetches the Debian source packages the Windows build compiles (GLFW and Dear ImGui: the versions
# the Linux build links) into DIR (default build-windows/sources), once. apt works on its own lists
# under DIR with one deb-src stanza per stanza of the system's sources (same archive, same suites),
# so the system's apt setup is not changed and no root is needed. Nothing is fetched from anywhere
# else, and nothing of it goes into the repository.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
dir="${1:-$root/build-windows/sources}"
packages=(glfw3 imgui)

done_marker="$dir/.fetched-${packages[*]// /-}"
[ -f "$done_marker" ] && exit 0
mkdir -p "$dir/apt/lists/partial" "$dir/apt/sources.list.d" "$dir/apt/cache/archives/partial"

# deb-src twins of the system's deb822 stanzas (and of one-line "deb" entries, if any).
src="$dir/apt/sources.list.d/fxlab-src.sources"
: >"$src"
for f in /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] || continue
  awk 'BEGIN{RS="";ORS="\n\n"} /(^|\n)Types:[^\n]*deb/ && /debian/ {sub(/Types:[^\n]*/,"Types: deb-src"); print}' "$f" >>"$src"
done
if [ -f /etc/apt/sources.list ]; then
  sed -n 's/^deb \(.*debian.*\)$/deb-src \1/p' /etc/apt/sources.list >"$dir/apt/sources.list"
else
  : >"$dir/apt/sources.list"
fi
[ -s "$src" ] || [ -s "$dir/apt/sources.list" ] || { echo "fetch_sources: no Debian archive in /etc/apt to mirror" >&2; exit 1; }

apt_opts=(-o "Dir::Etc::SourceList=$dir/apt/sources.list" -o "Dir::Etc::SourceParts=$dir/apt/sources.list.d"
          -o "Dir::State::Lists=$dir/apt/lists" -o "Dir::Cache=$dir/apt/cache" -o "Debug::NoLocking=1"
          -o "APT::Sandbox::User=$(id -un)")
apt-get "${apt_opts[@]}" update -qq
cd "$dir"
for p in "${packages[@]}"; do
  apt-get "${apt_opts[@]}" source -qq --only-source "$p" >/dev/null
done
touch "$done_marker"
