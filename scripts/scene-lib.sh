# SPDX-License-Identifier: Apache-2.0
# scene-lib.sh: sourced by the scene checks and scripts/bench-scenes.sh (run from the repository
# root). build_scene_stats builds build/scene-stats from scripts/scene-stats.c against
# build/libpree.a with the Makefile's flags; make runs only for what is missing (`make test`
# builds build/pree and the library before the checks run).
build_scene_stats() {
  [ -x build/pree ] || make -s build/pree >/dev/null || return 1
  [ -f build/libpree.a ] || make -s build/libpree.a >/dev/null || return 1
  local flags cflags ldflags ldlibs
  flags=$(make -pn build/pree 2>/dev/null)
  cflags=$(sed -n 's/^CFLAGS := //p' <<<"$flags" | sed 's/-MMD -MP//')
  ldflags=$(sed -n 's/^LDFLAGS := //p' <<<"$flags")
  ldlibs=$(sed -n 's/^LDLIBS := //p' <<<"$flags")
  if [ ! build/scene-stats -nt scripts/scene-stats.c ] || [ ! build/scene-stats -nt build/libpree.a ]; then
    # Private names, then one rename: checks that run at once may build it together.
    local tmp=build/scene-stats.$$
    gcc $cflags -c scripts/scene-stats.c -o $tmp.o &&
      g++ $ldflags $tmp.o build/libpree.a -o $tmp $ldlibs && mv -f $tmp build/scene-stats \
      || { rm -f $tmp $tmp.o; return 1; }
    rm -f $tmp.o
  fi
}
