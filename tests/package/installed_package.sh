#!/usr/bin/env bash
# The installed package, tested from the outside (docs/testing_controllers.md):
#
#   installed_package.sh example BUILD_DIR SOURCE_DIR
#     cmake --install BUILD_DIR into a temporary prefix; every installed program answers --help
#     (usage on stdout, exit 0); maneuver_runner and autopilot find the installed configuration
#     by bare name (--config zigzag_10_10, heading_step); the plotting scripts are installed and
#     start (--help) from there; then configures, builds and tests
#     SOURCE_DIR/examples/controller_ci against it (find_package(towsim) with
#     CMAKE_PREFIX_PATH=<prefix> only: nothing of the build or source tree)
#   installed_package.sh deb BUILD_DIR SOURCE_DIR
#     cpack -G DEB, then checks the package without installing it into this machine's /usr:
#     its Depends (from dpkg-shlibdeps) name the packages that own every shared library
#     sim_node needs; apt-get resolves them (--simulate); the extracted files (dpkg -x into a
#     throwaway root) hold the programs, the configuration and the CMake package, and the
#     extracted sim_node answers --help and runs an installed scene by name, offline and (in
#     its DDS program, usr/libexec/towsim/sim_node_dds) in --mode fast on domain 196.
#
# Registered as ctest tests InstalledPackage.ControllerCiExample / InstalledPackage.DebianPackage
# (tests/package/CMakeLists.txt). Everything is written under a temporary directory that is
# removed at the end, also on failure.
set -euo pipefail
mode="$1"
build="$(cd "$2" && pwd)"
source="$(cd "$3" && pwd)"
work="$(mktemp -d "${TMPDIR:-/tmp}/towsim_package.XXXXXX")"
trap 'rm -rf "$work"' EXIT
fail() { echo "installed_package.sh: FAIL: $*" >&2; exit 1; }

case "$mode" in
example)
  cmake --install "$build" --prefix "$work/prefix" > "$work/install.log" ||
    { cat "$work/install.log"; fail "cmake --install"; }
  for f in bin/sim_node bin/towfish_depth share/towsim/cyclonedds.xml \
           share/towsim/scenes/case1_forward.yaml share/towsim/line_types/park_kim_tow_cable.yaml \
           lib/cmake/towsim/towsimConfig.cmake \
           share/towsim/scripts/plot_paper.py share/towsim/scripts/plot_uturn_3d.py \
           share/towsim/scripts/plot_waves.py share/towsim/scripts/plot_sweep.py \
           share/towsim/scripts/paper_cases.py; do
    [[ -e "$work/prefix/$f" ]] || fail "the installation has no $f"
  done
  # every installed program (cmake/install.cmake TOWSIM_INSTALLED_PROGRAMS) answers --help
  programs=0
  for program in "$work/prefix"/bin/*; do
    name="$(basename "$program")"
    "$program" --help > "$work/help.txt" 2> "$work/help.err" ||
      fail "$name --help: exit $?: $(cat "$work/help.err")"
    grep -q "^usage: $name" "$work/help.txt" || fail "$name --help: no usage on stdout"
    programs=$((programs + 1))
  done
  [[ "$programs" -eq 11 ]] || fail "bin/ holds $programs programs, not the 11 of TOWSIM_INSTALLED_PROGRAMS"
  # a bare --config name finds the installed file (P/share/towsim/maneuvers, autopilot): the
  # file is read, then the bad --timeout is the error (exit 2); a name installed nowhere is
  # reported as the file it names
  for run in "maneuver_runner zigzag_10_10" "autopilot heading_step"; do
    read -r name config <<< "$run"
    set +e
    "$work/prefix/bin/$name" --config "$config" --timeout x > /dev/null 2> "$work/config.err"
    code=$?
    set -e
    [[ "$code" -eq 2 ]] && grep -q -- "--timeout x: not a number" "$work/config.err" ||
      fail "$name --config $config (installed): exit $code: $(cat "$work/config.err")"
  done
  set +e
  "$work/prefix/bin/maneuver_runner" --config zigzag_none > /dev/null 2> "$work/config.err"
  set -e
  grep -q "zigzag_none: cannot read the file" "$work/config.err" ||
    fail "maneuver_runner --config zigzag_none: $(cat "$work/config.err")"
  # the installed bridge writes the layout of an installed scene named bare: the shipped
  # layout is its output for case1_forward (docs/foxglove.md "A layout for any scene")
  "$work/prefix/bin/towsim_foxglove" --layout case1_forward --output "$work/layout.json" ||
    fail "towsim_foxglove --layout case1_forward (installed)"
  cmp -s "$work/layout.json" "$work/prefix/share/towsim/foxglove/towsim.json" ||
    fail "towsim_foxglove --layout case1_forward differs from share/towsim/foxglove/towsim.json"
  # the plotting scripts start from the installation (paper_cases.py beside them), where a
  # python3 with matplotlib is there to run them
  if /usr/bin/python3 -c "import matplotlib" 2> /dev/null; then
    for script in plot_paper plot_uturn_3d plot_waves plot_sweep; do
      /usr/bin/python3 "$work/prefix/share/towsim/scripts/$script.py" --help > /dev/null ||
        fail "share/towsim/scripts/$script.py --help"
    done
  else
    echo "note: /usr/bin/python3 has no matplotlib: the installed plotting scripts not started"
  fi
  cmake -S "$source/examples/controller_ci" -B "$work/example" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log" ||
    { cat "$work/configure.log"; fail "configuring examples/controller_ci"; }
  grep -q "towsim_DIR:PATH=$work/prefix/lib/cmake/towsim" "$work/example/CMakeCache.txt" ||
    fail "find_package(towsim) did not find the temporary prefix"
  cmake --build "$work/example" -j2 > "$work/build.log" ||
    { cat "$work/build.log"; fail "building examples/controller_ci"; }
  # the example's tests pick their DDS domain ids themselves (DomainLease)
  ctest --test-dir "$work/example" --output-on-failure
  ;;
deb)
  (cd "$work" && cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/cpack" \
     > "$work/cpack.log") || { cat "$work/cpack.log"; fail "cpack -G DEB"; }
  debs=("$work"/cpack/towsim_*.deb)
  [[ -f "${debs[0]}" ]] || fail "cpack made no towsim_*.deb"
  deb="${debs[0]}"
  echo "package: $(basename "$deb") ($(du -k "$deb" | cut -f1) kB)"
  depends="$(dpkg-deb -f "$deb" Depends)"
  echo "Depends: $depends"
  # the package names of Depends, one a line (versions and alternatives dropped)
  depends_names="$(tr ',' '\n' <<< "$depends" | sed 's/[(|].*//; s/ //g')"
  for pkg in libddsc0debian libyaml-cpp0.7 libstdc++6 libc6; do
    grep -qx "$pkg" <<< "$depends_names" || fail "Depends does not name $pkg"
  done
  dpkg -x "$deb" "$work/root"
  for f in usr/bin/sim_node usr/bin/towsim_record usr/bin/towsim_replay usr/bin/towsim_export \
           usr/bin/towfish_depth usr/share/towsim/cyclonedds.xml \
           usr/share/towsim/scenes/case1_forward.yaml usr/share/towsim/idl/towsim_msgs.idl \
           usr/share/towsim/ros2/towsim_msgs/package.xml usr/include/towsim/msgs/towsim_msgs.h \
           usr/share/towsim/scripts/plot_paper.py usr/share/towsim/maneuvers/zigzag_10_10.yaml \
           usr/include/towsim/common/client.h usr/include/towsim/wire/topic_names.h \
           usr/include/towsim/testing/sim_node_test.h \
           usr/lib/cmake/towsim/towsimConfig.cmake; do
    [[ -e "$work/root/$f" ]] || fail "the package has no /$f"
  done
  # every shared library sim_node and its DDS program (usr/libexec/towsim/sim_node_dds, which
  # sim_node execs for the DDS modes) link directly (NEEDED) belongs to a package Depends names
  # (the libraries those load are their packages' own dependencies)
  sim_node="$work/root/usr/bin/sim_node"
  for program in "$sim_node" "$work/root/usr/libexec/towsim/sim_node_dds"; do
    [[ -x "$program" ]] || fail "the package has no ${program#"$work/root"}"
    echo "${program#"$work/root"}:"
    while read -r needed; do
      lib="$(ldd "$program" | awk -v n="$needed" '$1 == n { print $3 }')"
      [[ -n "$lib" ]] || fail "$program needs $needed, which is not found"
      owner=""
      # /lib is /usr/lib on Debian 12 (merged /usr); dpkg knows one of the spellings
      for path in "$lib" "/usr$lib" "$(realpath "$lib")"; do
        [[ -n "$owner" ]] || owner="$( (dpkg -S "$path" 2>/dev/null || true) | head -1 | cut -d: -f1)"
      done
      [[ -n "$owner" ]] || fail "no Debian package owns $lib"
      grep -qx "$owner" <<< "$depends_names" ||
        fail "${program#"$work/root"} needs $lib of $owner, not in Depends"
      echo "  $needed: $owner"
    done < <(readelf -d "$program" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
  done
  # the offline sim_node loads no DDS library (docs/benchmarks.md, "Start-up")
  if readelf -d "$sim_node" | grep -q 'NEEDED.*libddsc'; then
    fail "usr/bin/sim_node links libddsc: the offline node must not load DDS"
  fi
  # apt resolves the dependencies (nothing is installed)
  apt-get install --simulate --no-install-recommends "$deb" > "$work/apt.log" 2>&1 ||
    { cat "$work/apt.log"; fail "apt-get install --simulate $deb"; }
  "$work/root/usr/bin/sim_node" --help > "$work/help.txt" || fail "sim_node --help"
  grep -q "^usage: sim_node --scene FILE" "$work/help.txt" || fail "sim_node --help: no usage"
  # the packaged sim_node finds the packaged scenes by name (<root>/usr/share/towsim/scenes)
  "$work/root/usr/bin/sim_node" --scene case1_forward --mode offline --duration 1 \
    > "$work/run.txt" || fail "sim_node --scene case1_forward (packaged)"
  grep -q "^sim_node: case1_forward: 20 steps" "$work/run.txt" || fail "$(cat "$work/run.txt")"
  # a packaged scene finds a line type of the packaged library by name
  # (<root>/usr/share/towsim/line_types, docs/scene_format.md "Line types")
  "$work/root/usr/bin/sim_node" --scene steady_tow --mode offline --duration 1 \
    --set "cable={line_type: park_kim_tow_cable, length: 200, elements: 20, start: {driven: \
{position: [0, 0, 3.5], velocity: [6, 0, 0]}}, end: {body: towfish}}" > "$work/run_lt.txt" ||
    fail "sim_node --scene steady_tow with line_type: park_kim_tow_cable (packaged)"
  grep -q "^sim_node: steady_tow: 20 steps" "$work/run_lt.txt" || fail "$(cat "$work/run_lt.txt")"
  # a DDS mode runs in the packaged DDS program, found beside the packaged sim_node
  # (<root>/usr/libexec/towsim), which finds the packaged scene and cyclonedds.xml itself;
  # domain 196 (tests/integration/README.md), inside a network namespace of its own if we may
  fast=("$work/root/usr/bin/sim_node" --scene case1_forward --mode fast --duration 1 --domain 196)
  if unshare -n true 2>/dev/null; then
    CYCLONEDDS_URI="file://$work/root/usr/share/towsim/cyclonedds.xml" \
      unshare -n bash -c 'ip link set lo up && exec "$@"' fast "${fast[@]}" \
      > "$work/fast.txt" 2> "$work/fast.err" || fail "packaged sim_node --mode fast: $(cat "$work/fast.err")"
  else
    CYCLONEDDS_URI="file://$work/root/usr/share/towsim/cyclonedds.xml" "${fast[@]}" \
      > "$work/fast.txt" 2> "$work/fast.err" || fail "packaged sim_node --mode fast: $(cat "$work/fast.err")"
  fi
  grep -q "^sim_node: case1_forward: fast, 20 steps" "$work/fast.txt" ||
    fail "packaged sim_node --mode fast: $(cat "$work/fast.txt" "$work/fast.err")"
  echo "ok: $(basename "$deb"): Depends complete, files present, sim_node runs"
  ;;
*)
  fail "mode must be example or deb, not '$mode'"
  ;;
esac
