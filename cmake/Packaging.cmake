# `cpack -G DEB` and `cpack -G TGZ` from the build folder (docs/install.md).
#
# The Debian package installs under /opt/radcl rather than /usr: radcl replaces only rtrace and
# rpict (plus gensky and gendaylit), and Radiance users keep Radiance's other tools (oconv, pfilt,
# falsecolor, ...) from Debian's `radiance` package, whose /usr/bin/rtrace it would clash with.
# Users put /opt/radcl/bin first on PATH.
set(CPACK_PACKAGE_NAME radcl)
set(CPACK_PACKAGE_VENDOR "radcl")
set(CPACK_PACKAGE_CONTACT "radcl maintainers <radcl@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Radiance-compatible rtrace, rpict and rcontrib with OpenCL shading and Embree traversal")
set(CPACK_PACKAGE_DESCRIPTION
    "radcl reads Radiance scenes and octrees, takes rtrace's, rpict's and rcontrib's options and writes their outputs and .amb cache files; shading runs in OpenCL kernels (PoCL on the CPU, or a GPU).")
set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE")
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR "DEB;TGZ")

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # radcl_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON) # the libraries' packages, from dpkg-shlibdeps
# An OpenCL driver to run the kernels on: PoCL on the CPU unless another one is installed.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "pocl-opencl-icd | opencl-icd")
# Per generator (CPackOptions.cmake): the .deb's prefix is /opt/radcl, the tarball's its root.
configure_file(${PROJECT_SOURCE_DIR}/cmake/CPackOptions.cmake.in
               ${PROJECT_BINARY_DIR}/CPackOptions.cmake @ONLY)
set(CPACK_PROJECT_CONFIG_FILE ${PROJECT_BINARY_DIR}/CPackOptions.cmake)

# The tarball unpacks to radcl-<version>-Linux/{bin,lib,share}: run it from wherever it lands.
set(CPACK_ARCHIVE_COMPONENT_INSTALL OFF)

include(CPack)
