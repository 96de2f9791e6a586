# Warnings and standard settings applied to every sdfwb target.
function(sdfwb_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Werror=switch -Werror=return-type)
  target_compile_features(${target} PUBLIC cxx_std_20)
endfunction()

# sdfwb_module(NAME SOURCES ... DEPS ... [PRIVATE_DEPS ...])
# One static library per module, aliased sdfwb::NAME, exposing only NAME/include.
function(sdfwb_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(sdfwb_${name} STATIC ${ARG_SOURCES})
  add_library(sdfwb::${name} ALIAS sdfwb_${name})
  target_include_directories(sdfwb_${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(sdfwb_${name} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  set_target_properties(sdfwb_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  sdfwb_target_defaults(sdfwb_${name})
endfunction()
