#!/usr/bin/env bash
# How much a first write to memory costs this machine, against a write to memory the process has
# written before: the reason for the allocator settings in the Makefile (issue 44). A new process
# maps SIZE MiB, writes it twice and reports both rates in GB/s, with small pages and then with
# huge pages, once right after the previous process freed the same amount and once WAIT seconds
# later. On a virtual machine whose balloon hands freed pages back to the host, the first write
# after a wait is the slow one, and it counts as system time.
# Usage: scripts/first_write.sh [SIZE_MIB] [WAIT_SECONDS]     (defaults 1024 and 3)
set -eu
size=${1:-1024}
wait=${2:-3}
case "$size$wait" in *[!0-9]*) echo "first_write: SIZE_MIB and WAIT_SECONDS must be whole numbers" >&2; exit 2 ;; esac
[ "$size" -ge 16 ] && [ "$size" -le 8192 ] || { echo "first_write: SIZE_MIB must lie in 16 ... 8192" >&2; exit 2; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cat > "$dir/w.c" <<'C'
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>
static double now(void) { struct timespec t; clock_gettime(CLOCK_MONOTONIC, &t); return t.tv_sec + 1e-9 * t.tv_nsec; }
int main(int argc, char** argv) {
  size_t n = (size_t)atol(argv[1]) << 20;
  int huge = atoi(argv[2]);
  char* p = mmap(0, n, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) { perror("first_write: mmap"); return 1; }
  madvise(p, n, huge ? MADV_HUGEPAGE : MADV_NOHUGEPAGE);
  double t0 = now(); memset(p, 1, n); double t1 = now(); memset(p, 2, n); double t2 = now();
  printf("%6.2f GB/s first write, %6.2f GB/s second\n", n / 1e9 / (t1 - t0), n / 1e9 / (t2 - t1));
  return p[n - 1] != 2;
}
C
cc -O2 -o "$dir/w" "$dir/w.c"
# With transparent huge pages set to "never", the huge-page lines measure small pages: say which.
thp=/sys/kernel/mm/transparent_hugepage/enabled
echo "transparent huge pages: $(cat "$thp" 2>/dev/null || echo "unknown (no $thp)")"
for huge in 0 1; do
  label=$([ "$huge" = 1 ] && echo "huge pages" || echo "4 KiB pages")
  "$dir/w" "$size" "$huge" > /dev/null
  printf '%-12s right after another: %s\n' "$label" "$("$dir/w" "$size" "$huge")"
  sleep "$wait"
  printf '%-12s %2s s later:          %s\n' "$label" "$wait" "$("$dir/w" "$size" "$huge")"
done
