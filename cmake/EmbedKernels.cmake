# Embeds every OpenCL source under kernels/ and the plain-C headers shared with the device
# (include/radcl/*.h) into the executables, so a moved or installed binary needs no source tree.
file(GLOB_RECURSE RADCL_KERNEL_FILES CONFIGURE_DEPENDS
     ${PROJECT_SOURCE_DIR}/kernels/*.cl ${PROJECT_SOURCE_DIR}/kernels/*.h)
file(GLOB RADCL_SHARED_HEADERS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/include/radcl/*.h
     ${PROJECT_SOURCE_DIR}/include/radcl/calc/device_context.h
     ${PROJECT_SOURCE_DIR}/include/radcl/calc/noise.h)
set(RADCL_EMBEDDED_CPP ${CMAKE_BINARY_DIR}/generated/embedded_kernels.cpp)
# Called from the directory that owns the target using the file (custom-command outputs are
# visible only there).
macro(radcl_embed_kernels_rule)
# '|' separates the list: a ';' would split the command line.
string(REPLACE ";" "|" _radcl_embed_list "${RADCL_KERNEL_FILES};${RADCL_SHARED_HEADERS}")
add_custom_command(
  OUTPUT ${RADCL_EMBEDDED_CPP}
  COMMAND ${CMAKE_COMMAND} -DROOT=${PROJECT_SOURCE_DIR} -DOUT=${RADCL_EMBEDDED_CPP}
          "-DFILES=${_radcl_embed_list}"
          -P ${PROJECT_SOURCE_DIR}/cmake/embed_files.cmake
  DEPENDS ${RADCL_KERNEL_FILES} ${RADCL_SHARED_HEADERS} ${PROJECT_SOURCE_DIR}/cmake/embed_files.cmake
  COMMENT "Embedding OpenCL kernel sources"
  VERBATIM)
endmacro()
