# radcl_module(NAME DEPS ...): one static library per module folder src/<name>/, public headers
# in include/radcl/<name>/. Sources are globbed so a new file needs no CMake edit.
function(radcl_module name)
  cmake_parse_arguments(ARG "" "" "DEPS;PRIVATE_DEPS;EXTRA_SOURCES" ${ARGN})
  file(GLOB _src CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${name}/*.cpp)
  add_library(radcl_${name} STATIC ${_src} ${ARG_EXTRA_SOURCES})
  target_include_directories(radcl_${name} PUBLIC ${PROJECT_SOURCE_DIR}/include)
  target_link_libraries(radcl_${name} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
endfunction()
