#!/usr/bin/env bash
# Installs (apt-get, as root) every package of the given lists that is not installed yet.
# Usage: tools/packages/install.sh LIST.txt [LIST.txt...]  — the lists are one package a line.
set -euo pipefail
packages=()
for list in "$@"; do
  while read -r line; do
    line=${line%%#*}
    line=${line//[[:space:]]/}
    [ -n "$line" ] && packages+=("$line")
  done < "$list"
done
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
