# pcl_tda_add_library(<module> SOURCES <src>... LINK <target>...)
#
# Adds the shared library pcl_tda_<module> of one module folder, with its public
# headers under <module>/include, exported as pcl_tda::<module>, the package
# component <module> (its own export set, so that a user finds only what it links).
function(pcl_tda_add_library module)
  cmake_parse_arguments(ARG "" "" "SOURCES;LINK" ${ARGN})
  set(target pcl_tda_${module})
  add_library(${target} SHARED ${ARG_SOURCES})
  add_library(pcl_tda::${module} ALIAS ${target})
  # Installed, a library finds the modules it builds on beside itself.
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${module}
                                             VERSION ${PROJECT_VERSION}
                                             INSTALL_RPATH "$ORIGIN")
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/pcl_tda>)
  target_link_libraries(${target} PUBLIC ${ARG_LINK})
  set_property(GLOBAL APPEND PROPERTY PCL_TDA_MODULES ${module})
  install(TARGETS ${target} EXPORT pcl_tda_${module}Targets
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/pcl_tda)
endfunction()

# pcl_tda_add_tool(<name> SOURCES <src>... LINK <target>...)
#
# Adds the command-line tool pcl_tda_<name>, installed beside PCL's own tools.
function(pcl_tda_add_tool name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LINK" ${ARGN})
  add_executable(pcl_tda_${name} ${ARG_SOURCES})
  target_link_libraries(pcl_tda_${name} PRIVATE ${ARG_LINK})
  # Only the shared libraries a tool calls: PCL's io library loads VTK, which takes
  # 20 ms at every start of a tool that reads PCD files without it (pcl_tda_barcode).
  target_link_options(pcl_tda_${name} PRIVATE LINKER:--as-needed)
  # Installed, a tool finds the libraries in the prefix it is installed in.
  set_target_properties(pcl_tda_${name} PROPERTIES
    INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")
  install(TARGETS pcl_tda_${name} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endfunction()
