#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# usage: scripts/check-format.sh [BASE]
#
# Checks that every line of C++ changed since BASE (default: the commit that added .clang-format)
# is as clang-format 14 (Debian bookworm's) formats it with .clang-format. Older lines are left as
# they were written. Prints what to change and fails otherwise; `git clang-format-14 BASE` applies it.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! git rev-parse --git-dir > /dev/null 2>&1; then
  echo "check-format: not a git checkout: nothing to compare with"
  exit 0
fi
base=${1:-$(git log --diff-filter=A --format=%H -- .clang-format | tail -n 1)}
if [ -z "$base" ] || ! git cat-file -e "$base^{commit}" 2> /dev/null; then
  echo "check-format: the commit that added .clang-format is not in this clone: nothing to compare with"
  exit 0
fi
out=$(git clang-format-14 --binary clang-format-14 --style file --extensions c,cc,cpp,h,hpp --diff "$base" 2>&1) || true
case "$out" in
  "no modified files to format" | "clang-format did not modify any files" | "")
    echo "check-format: every C++ line changed since ${base:0:12} is formatted"
    ;;
  *)
    echo "$out"
    echo "check-format: the lines above are not formatted; git clang-format-14 ${base:0:12} formats them" >&2
    exit 1
    ;;
esac
