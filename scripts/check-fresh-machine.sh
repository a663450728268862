#!/usr/bin/env bash
# Proves the README's quick start on a fresh Debian 12 machine: builds a minimal Debian 12
# root (debootstrap --variant=minbase), clones this repository's HEAD into it and runs
#   ./run.sh        (install what is missing, build, run the main job)
#   ./run.sh test   (install what is missing, build, run the whole test suite)
# inside it, printing the time of each and the last lines of a failure.
#
# Usage: scripts/check-fresh-machine.sh [--preflight] [--keep] [--no-cache] [--with-slurm]
#                                       [--with-sanitizers]
#   --preflight  only say whether the check can run here (exit 0) or why not (exit 77)
#   --keep       keep the root afterwards (its path is printed)
#   --no-cache   rebuild the bare root with debootstrap even when a cached one exists
#   --with-slurm between the two commands, also `scripts/setup.sh --with-slurm` (the optional
#                Slurm and munge packages), so that the test of the Slurm scripts runs in the
#                root instead of being skipped
#   --with-sanitizers after the two commands, `scripts/setup.sh --with-sanitizers` (clang) and
#                scripts/sanitize.sh: the suite under ASan+UBSan and a smoke run of every
#                fuzz target (docs/fuzzing.md)
#
# The mirror comes from this machine's own apt configuration (never a host written here).
# The bare root (nothing but debootstrap's minbase) is cached as a tarball under
# ${XDG_CACHE_HOME:-~/.cache}/signstim/ so later runs skip debootstrap; the project's own
# packages are never cached: each run installs them afresh, as a new user's machine would.
# Needs root (chroot, mounts). Exit status: 0 both commands passed, 1 one failed,
# 77 the check cannot run here (not root, no debootstrap, mirror unreachable).
set -euo pipefail

preflight=0 keep=0 use_cache=1 with_slurm=0 with_sanitizers=0
for arg in "$@"; do
  case "$arg" in
    --preflight) preflight=1 ;;
    --keep) keep=1 ;;
    --no-cache) use_cache=0 ;;
    --with-slurm) with_slurm=1 ;;
    --with-sanitizers) with_sanitizers=1 ;;
    -h|--help) sed -n '2,25p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "check-fresh-machine: unknown option '$arg' (see --help)" >&2; exit 1 ;;
  esac
done

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
say() { echo "check-fresh-machine: $*"; }
cannot() { say "cannot run here: $*"; exit 77; }

# ---- can it run here? --------------------------------------------------------------------
[[ $(id -u) -eq 0 ]] || cannot "needs root (chroot and bind mounts)"
command -v git >/dev/null || cannot "git is missing"
arch=$(dpkg --print-architecture 2>/dev/null) || cannot "not a Debian system (no dpkg)"

# The Debian mirror this machine's apt uses for bookworm, and for its security updates.
origin_of() {  # $1: suite -> base URI (e.g. http://deb.debian.org/debian), or nothing
  apt-cache policy 2>/dev/null |
    awk -v suite="$1/main" '$3 == suite && $2 ~ /^(https?|file):/ {print $2; exit}'
}
mirror=$(origin_of bookworm)
[[ -n $mirror ]] || cannot "this machine's apt configuration names no Debian bookworm mirror"
security=$(origin_of bookworm-security)
updates=$(origin_of bookworm-updates)

reachable() {  # plain HTTP HEAD of the suite's Release file, 15 s at most
  local uri=$1 host path
  [[ $uri == http://* ]] || return 0  # https/file: let debootstrap find out
  host=${uri#http://}; path=/${host#*/}; host=${host%%/*}
  [[ $path == "/$host" ]] && path=/
  timeout 15 bash -c '
    exec 3<>"/dev/tcp/$1/80" || exit 1
    printf "HEAD %s/dists/bookworm/Release HTTP/1.1\r\nHost: %s\r\nConnection: close\r\n\r\n" "${2%/}" "$1" >&3
    IFS= read -r status <&3 && [[ $status =~ ^HTTP/[0-9.]+\ [23] ]]' _ "$host" "$path" 2>/dev/null
}
reachable "$mirror" || cannot "the mirror $mirror does not answer"

if ! command -v debootstrap >/dev/null; then
  if ((preflight)); then
    apt-cache show debootstrap >/dev/null 2>&1 || cannot "debootstrap is neither installed nor installable"
  else
    say "installing debootstrap"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends debootstrap >/dev/null 2>&1 ||
      { apt-get update -q >/dev/null 2>&1 &&
        DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends debootstrap >/dev/null 2>&1; } ||
      cannot "debootstrap is missing and could not be installed"
  fi
fi
if ((preflight)); then say "can run (mirror $mirror)"; exit 0; fi

# ---- the root ----------------------------------------------------------------------------
cache_dir=${XDG_CACHE_HOME:-$HOME/.cache}/signstim
cache_key=$(printf '%s %s' "$mirror" "$arch" | sha256sum | cut -c1-12)
cache=$cache_dir/debian12-minbase-$arch-$cache_key.tar
work=$(mktemp -d "${TMPDIR:-/var/tmp}/signstim-fresh.XXXXXX")
root=$work/root
mounted=()

cleanup() {
  local status=$?
  trap - EXIT INT TERM HUP
  local m
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    m=${mounted[i]}
    umount "$m" 2>/dev/null || umount -l "$m" 2>/dev/null || say "could not unmount $m"
  done
  if ((keep)) && ((status != 130 && status != 143)); then
    say "root kept at $root"
  else
    # Only once nothing is mounted below it: rm -rf must never walk into the host's /proc or /dev.
    if ! grep -q " $root/" /proc/self/mounts 2>/dev/null; then rm -rf "$work"; else say "left $work (still mounted)"; fi
  fi
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
trap 'exit 129' HUP

t0=$SECONDS
mkdir -p "$root"
if ((use_cache)) && [[ -s $cache ]]; then
  say "bare Debian 12 root from the cache ($cache)"
  tar -xf "$cache" -C "$root"
else
  say "building a bare Debian 12 root with debootstrap --variant=minbase from $mirror (cached afterwards)"
  log=$work/debootstrap.log
  if ! debootstrap --variant=minbase bookworm "$root" "$mirror" >"$log" 2>&1; then
    say "debootstrap failed; its last lines:"; tail -n 20 "$log"; exit 1
  fi
  mkdir -p "$cache_dir"
  tar -cf "$cache.tmp-$$" -C "$root" . && mv "$cache.tmp-$$" "$cache"
fi
{
  echo "deb $mirror bookworm main"
  [[ -n $updates ]] && echo "deb $updates bookworm-updates main"
  [[ -n $security ]] && echo "deb $security bookworm-security main"
} >"$root/etc/apt/sources.list"
rm -f "$root"/etc/apt/sources.list.d/*
cp -L /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
# What an installed Debian has and debootstrap's minbase lacks: /etc/hosts (without it
# "localhost" does not resolve, and Selenium cannot reach chromedriver on localhost).
[[ -e $root/etc/hosts ]] || printf '127.0.0.1\tlocalhost\n::1\t\tlocalhost ip6-localhost ip6-loopback\n' >"$root/etc/hosts"
# This machine's own local certificate authorities (a site's HTTPS proxy), as its resolver
# and mirror above: the ca-certificates package that setup installs in the root picks them up.
if compgen -G "/usr/local/share/ca-certificates/*.crt" >/dev/null; then
  mkdir -p "$root/usr/local/share/ca-certificates"
  cp /usr/local/share/ca-certificates/*.crt "$root/usr/local/share/ca-certificates/"
fi
say "root ready in $((SECONDS - t0)) s"

for m in proc sys dev dev/pts; do
  mkdir -p "$root/$m"
  case $m in
    proc) mount -t proc proc "$root/proc" ;;
    sys) mount --rbind /sys "$root/sys"; mount --make-rslave "$root/sys" ;;
    dev) mount --rbind /dev "$root/dev"; mount --make-rslave "$root/dev" ;;
    dev/pts) continue ;;  # came with the recursive /dev bind
  esac
  mounted+=("$root/$m")
done
mkdir -p "$root/tmp" && chmod 1777 "$root/tmp"

# The repository's HEAD, as a user's clone (uncommitted changes are not part of it).
git clone -q --no-hardlinks "$repo" "$root/home/signstim"
say "cloned $(git -C "$repo" rev-parse --short HEAD) into the root"

run_in_root() {  # $1: label, rest: the command, in the clone
  local label=$1; shift
  local log=$work/$label.log start=$SECONDS status=0
  say "--- $label: $* ---"
  set +e
  chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    LANG=C.UTF-8 TERM=dumb CI="${CI:-}" bash -c 'cd /home/signstim && "$@"' _ "$@" 2>&1 | tee "$log"
  status=${PIPESTATUS[0]}
  set -e
  local took=$((SECONDS - start))
  times+=("$label: $((took / 60)) min $((took % 60)) s (exit $status)")
  if ((status != 0)); then
    say "$label FAILED (exit $status) after ${took} s; its last lines:"
    tail -n 40 "$log" | sed 's/^/  | /'
    return 1
  fi
}

times=()
failed=0
run_in_root "main-job" ./run.sh || failed=1
if ((with_slurm)) && ! ((failed)); then run_in_root "slurm-packages" scripts/setup.sh --with-slurm || failed=1; fi
((failed)) || run_in_root "test-suite" ./run.sh test || failed=1
if ((with_sanitizers)) && ! ((failed)); then
  run_in_root "sanitizer-packages" scripts/setup.sh --with-sanitizers || failed=1
  ((failed)) || run_in_root "sanitizer-suite" scripts/sanitize.sh || failed=1
fi

say "times on this machine ($(nproc) cores):"
printf '  %s\n' "${times[@]}"
((failed)) && { say "FAILED on a fresh Debian 12 root (above)"; exit 1; }
say "passed: both README commands work on a fresh Debian 12 root$( ((with_sanitizers)) && echo ", and the sanitizer suite and fuzz smoke runs are clean")"
