#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# The licence header of every source, script and build file: an SPDX identifier and a copyright line, in the
# file's own comment syntax, first in the file (after a shebang).
#
#   bash ci/spdx.sh --check [ROOT]   lists the files without both lines; exit 1 if any (0 otherwise)
#   bash ci/spdx.sh --fix [ROOT]     adds the two lines where they are missing (idempotent)
#   bash ci/spdx.sh --list [ROOT]    the files covered
#   bash ci/spdx.sh --verify-fix [ROOT]  --fix on a copy of the covered files: afterwards --check passes, a second
#                                    --fix changes nothing, each file only gained lines at its top, and the shell
#                                    scripts and Python files still parse
#
# Covered: C and C++ sources and headers, Python, shell, CMake (CMakeLists.txt, *.cmake, *.in templates),
# pyproject.toml, sanitizer suppressions, .ci/run. Not covered: data and documents (scenes, matrices and other
# YAML, PLY, JSON, images, Markdown), fuzz corpora and regressions (inputs replayed byte for byte) and shim/abi/1.<m>/
# (the released 1.0 header and the abidw baselines are kept unmodified). ROOT defaults to the repository.
set -euo pipefail

SPDX="SPDX-License-Identifier: Apache-2.0"
COPYRIGHT="Copyright 2026 The stipple authors"

# The whole script is one function, read by bash before it runs: --fix may rewrite this very file.
main() {
  mode=${1:-}
  root=${2:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
  case $mode in --check | --fix | --list | --verify-fix) ;; *) sed -n '2,15p' "$0" >&2; exit 2 ;; esac
  cd "$root"

  covered() {
    local files
    if git rev-parse --is-inside-work-tree >/dev/null 2>&1 && [ "$(git rev-parse --show-toplevel)" = "$(pwd -P)" ]; then
      files=$(git ls-files --cached --others --exclude-standard)
    else
      files=$(find . -path ./.git -prune -o -path ./build -prune -o -path ./report -prune -o -type f -print |
              sed 's|^\./||')
    fi
    grep -E '(\.(c|cpp|h|hpp|py|sh|cmake|in|supp)|(^|/)CMakeLists\.txt|(^|/)pyproject\.toml|^\.ci/run)$' <<<"$files" |
      grep -vE '(^|/)fuzz/[^/]*(corpus|regressions)/|^shim/abi/1\.[0-9]+/' | sort || true
  }

  # The comment syntax of a file: "//", "/*" (C files written with block comments) or "#".
  syntax() {
    case $1 in
      *.c | *.cpp | *.h | *.hpp | *.h.in)
        if head -n1 "$1" | grep -q '^/\*'; then echo '/*'; else echo '//'; fi ;;
      *) echo '#' ;;
    esac
  }

  # The covered files without both lines in their first five (one awk over all of them; an empty file has none).
  without_header() {
    local files
    files=$(covered)
    [ -n "$files" ] || return 0
    while IFS= read -r file; do [ -s "$file" ] || echo "$file"; done <<<"$files"
    tr '\n' '\0' <<<"$files" | xargs -0 awk -v s="$SPDX" -v c="$COPYRIGHT" '
      function finish() { if (name != "" && !(a && b)) print name }
      FNR == 1 { finish(); name = FILENAME; a = b = 0 }
      FNR <= 5 { if (index($0, s)) a = 1; if (index($0, c)) b = 1 }
      END { finish() }'
  }

  add_header() {
    local file=$1 open close
    case $(syntax "$file") in
      '//') open='// ' close='' ;;
      '/*') open='/* ' close=' */' ;;
      '#') open='# ' close='' ;;
    esac
    local tmp
    tmp=$(mktemp)
    awk -v a="$open$SPDX$close" -v b="$open$COPYRIGHT$close" -v prefix="${open% }" '
      function header(next_line) {
        print a; print b
        if (next_line != "" && index(next_line, prefix) != 1) print ""
      }
      NR == 1 && /^#!/ { print; shebang = 1; next }
      !done { header($0); done = 1 }
      { print }
      END { if (!done) { if (shebang || NR == 0) header("") } }
    ' "$file" >"$tmp"
    cat "$tmp" >"$file" # keeps the file's mode
    rm -f "$tmp"
  }

  if [ "$mode" = --verify-fix ]; then
    copy=$(mktemp -d)
    trap 'rm -rf "$copy" "$copy.orig"' EXIT
    covered | tr '\n' '\0' | tar --null -cf - -T - | tar -xf - -C "$copy"
    cp -a "$copy" "$copy.orig"
    bash "$0" --fix "$copy" >/dev/null
    bash "$0" --check "$copy"
    [ -z "$(bash "$0" --fix "$copy")" ] || { echo "spdx: a second --fix changed files" >&2; exit 1; }
    failures=0
    # Only additions, and only the two lines and a blank one.
    changes=$(diff -r "$copy.orig" "$copy" | grep -E '^[<>]' || true)
    if grep -q '^<' <<<"$changes" ||
       grep -vxE "> ((// |/\\* |# )($SPDX|$COPYRIGHT)( \\*/)?)?" <<<"$changes" | grep -q .; then
      echo "spdx: --fix changed more than the files' top lines:" >&2
      diff -r "$copy.orig" "$copy" | grep -E '^(diff|<|>)' | grep -vxE "> ((// |/\\* |# )($SPDX|$COPYRIGHT)( \\*/)?)?" |
        head -n 20 >&2
      failures=$((failures + 1))
    fi
    while IFS= read -r file; do
      bash -n "$copy/$file" || failures=$((failures + 1))
    done < <(covered | grep -E '\.sh$|^\.ci/run$')
    covered | grep '\.py$' | sed "s|^|$copy/|" |
      python3 -c 'import ast, sys; [ast.parse(open(f.strip()).read(), f.strip()) for f in sys.stdin]' ||
      failures=$((failures + 1))
    [ "$failures" -eq 0 ] || exit 1
    echo "spdx: --fix verified on a copy of $(covered | wc -l) files"
    exit 0
  fi

  case $mode in
    --list) covered ;;
    --check)
      missing=$(without_header | sort -u)
      while IFS= read -r file; do
        [ -n "$file" ] && echo "spdx: $file: no '$SPDX' and '$COPYRIGHT' lines at the top"
      done <<<"$missing"
      if [ -n "$missing" ]; then
        echo "spdx: $(wc -l <<<"$missing") file(s) without the licence header; bash ci/spdx.sh --fix adds it" >&2
        exit 1
      fi
      echo "spdx: every covered file has the licence header" ;;
    --fix)
      without_header | sort -u | while IFS= read -r file; do add_header "$file"; echo "spdx: added to $file"; done ;;
  esac
}

main "$@"; exit
