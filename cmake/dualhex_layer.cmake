# dualhex_add_layer(NAME SOURCES ... [DEPS ...])
# One static library per layer folder: NAME/include/dualhex/NAME/*.hpp (public, installed)
# and NAME/src/*.cpp. Exported as dualhex::NAME.
function(dualhex_add_layer name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_library(dualhex_${name} ${ARG_SOURCES})
  add_library(dualhex::${name} ALIAS dualhex_${name})
  set_target_properties(dualhex_${name} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME dualhex_${name})
  target_include_directories(dualhex_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(dualhex_${name} PUBLIC cxx_std_20)
  target_link_libraries(dualhex_${name} PUBLIC ${ARG_DEPS})
  install(TARGETS dualhex_${name} EXPORT dualhexTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/include)  # a layer may have no public header yet
    install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endfunction()
