# The exported CMake package: find_package(PCL_TDA [COMPONENTS common search ...])
# then link pcl_tda::common, pcl_tda::search, ... Each module is a component with its
# own export set; the config finds only the PCL parts the requested components need.
include(CMakePackageConfigHelpers)
set(PCL_TDA_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/PCL_TDA)
get_property(PCL_TDA_MODULES GLOBAL PROPERTY PCL_TDA_MODULES)
foreach(module IN LISTS PCL_TDA_MODULES)
  install(EXPORT pcl_tda_${module}Targets NAMESPACE pcl_tda::
          DESTINATION ${PCL_TDA_CMAKE_DIR})
endforeach()
configure_package_config_file(cmake/PCL_TDAConfig.cmake.in
  ${CMAKE_BINARY_DIR}/PCL_TDAConfig.cmake INSTALL_DESTINATION ${PCL_TDA_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/PCL_TDAConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/PCL_TDAConfig.cmake
              ${CMAKE_BINARY_DIR}/PCL_TDAConfigVersion.cmake
        DESTINATION ${PCL_TDA_CMAKE_DIR})
