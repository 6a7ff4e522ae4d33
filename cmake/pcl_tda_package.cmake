# The exported CMake package: find_package(PCL_TDA) then link pcl_tda::common,
# pcl_tda::search, ...
include(CMakePackageConfigHelpers)
set(PCL_TDA_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/PCL_TDA)
install(EXPORT pcl_tdaTargets NAMESPACE pcl_tda:: DESTINATION ${PCL_TDA_CMAKE_DIR})
configure_package_config_file(cmake/PCL_TDAConfig.cmake.in
  ${CMAKE_BINARY_DIR}/PCL_TDAConfig.cmake INSTALL_DESTINATION ${PCL_TDA_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/PCL_TDAConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/PCL_TDAConfig.cmake
              ${CMAKE_BINARY_DIR}/PCL_TDAConfigVersion.cmake
        DESTINATION ${PCL_TDA_CMAKE_DIR})
