# cpack -G DEB (from build/): towsim_<version>_<arch>.deb with what cmake --install installs,
# under /usr. Depends: the shared libraries the programs link (libddsc0debian, libyaml-cpp0.7,
# libstdc++6, libc6), found by dpkg-shlibdeps (dpkg-dev, which build-essential brings).
# Suggests: what building a controller or a test against find_package(towsim) needs.
set(CPACK_PACKAGE_NAME towsim)
set(CPACK_PACKAGE_VENDOR "towsim")
set(CPACK_PACKAGE_CONTACT "towsim maintainers <towsim@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Towed underwater system simulator (ANCF cable, 6-DOF vehicles) as a Cyclone DDS node")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # towsim_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "cmake, g++, cyclonedds-dev, libgtest-dev")
include(CPack)
