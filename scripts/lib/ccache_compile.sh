#!/bin/bash
# The compiler launcher of every build tree (CMakeLists.txt): ccache_compile.sh ROOT CCACHE
# COMPILER ARGS... compiles through CCACHE; a precompiled header is compiled directly (below), and
# clang's gets a path-free digest beside it.
#
# Why: clang writes the clone's paths into a .pch, and ccache puts a header's .pch into the key
# of every file compiled with it, so a second clone of the same sources missed on every file of
# the sanitizer trees. With pch_external_checksum (CCACHE_PCH_EXTSUM) ccache hashes <pch>.sum instead
# when there is one; this writes there a digest of what the header is made of — the command and
# the preprocessed header (every line of every file it includes), the clone's paths taken out.
set -u
root=$1 ccache=$2
shift 2
# ccache makes paths relative to the repository (CCACHE_BASEDIR) in the options it knows, but
# not in the header a file is compiled with, given as "-Xclang -include -Xclang ABSOLUTE": that
# one is made relative here (to the build folder it runs in), so that it names no clone either.
args=()
for arg in "$@"; do
  if [[ ${#args[@]} -gt 0 && ${args[-1]} == -Xclang && $arg == "$root"/*/cmake_pch.hxx ]]; then
    arg=$(realpath --relative-to=. "$arg")
  fi
  args+=("$arg")
done
out="" pch=0
for ((i = 0; i < ${#args[@]}; i++)); do
  case ${args[i]} in
    -emit-pch) pch=1 ;;
    -o) out=${args[i + 1]} ;;
  esac
done
# A precompiled header itself is compiled, never taken from the cache: it names the files it
# was made from by their absolute paths, and clang refuses one whose files are gone, so a .pch
# another clone made must not come out of the cache (its key, paths made relative, would match).
if [ "$pch" = 0 ]; then
  exec "$ccache" "${args[@]}"
fi
"${args[@]}" || exit
[ -n "$out" ] || exit 0

# The same command, preprocessing only: no -emit-pch, object, dependency file or codegen flags.
pre=()
for ((i = 0; i < ${#args[@]}; i++)); do
  case ${args[i]} in
    -o | -MT | -MF | -MQ) i=$((i + 1)) ;;
    -c | -MD | -MMD | -fpch-codegen | -fpch-instantiate-templates) ;;
    -Xclang)
      if [ "${args[i + 1]}" = -emit-pch ]; then i=$((i + 1)); else pre+=("${args[i]}"); fi ;;
    *) pre+=("${args[i]}") ;;
  esac
done
{
  printf '%s\n' "${args[@]}"
  "${pre[@]}" -Wno-unused-command-line-argument -E -o - || exit
} | sed "s|$root|<root>|g" | sha256sum | cut -d' ' -f1 > "$out.sum.tmp" && mv "$out.sum.tmp" "$out.sum"
