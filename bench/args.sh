# Sourced by the bench scripts that take `[path/to/rb] [-n RUNS]`: sets `rb` (default: the
# build tree's rb) and `runs` (default: the value of `runs` before sourcing).
bench_root="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rb="$bench_root/../build/cmd/rb"
while [ $# -gt 0 ]; do
  case "$1" in
    -n) runs="$2"; shift 2 ;;
    *) rb="$1"; shift ;;
  esac
done
