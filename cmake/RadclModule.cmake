# radcl_module(NAME DEPS ...): one static library per module folder src/<name>/, public headers
# in include/radcl/<name>/. Sources are globbed so a new file needs no CMake edit. A part of a
# module (NAME "render/pipeline") is the library radcl_render_pipeline.
function(radcl_module name)
  cmake_parse_arguments(ARG "" "" "DEPS;PRIVATE_DEPS;EXTRA_SOURCES" ${ARGN})
  file(GLOB _src CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${name}/*.cpp)
  string(REPLACE "/" "_" _target "radcl_${name}")
  add_library(${_target} STATIC ${_src} ${ARG_EXTRA_SOURCES})
  target_include_directories(${_target} PUBLIC ${PROJECT_SOURCE_DIR}/include)
  target_link_libraries(${_target} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
endfunction()
