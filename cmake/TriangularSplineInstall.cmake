# cmake --install: the headers, the tool, the Python module (when built) and the CMake package
# Triangular_splineConfig.cmake, which defines CGAL::Triangular_spline for
#   find_package(Triangular_spline REQUIRED)
#   target_link_libraries(app PRIVATE CGAL::Triangular_spline)
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT Development)

# The target is exported as "Triangular_spline" and named CGAL::Triangular_spline by the
# namespace, as the alias of the build tree.
install(TARGETS Triangular_spline EXPORT Triangular_splineTargets)
set(TRIANGULAR_SPLINE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Triangular_spline)
install(EXPORT Triangular_splineTargets NAMESPACE CGAL:: DESTINATION ${TRIANGULAR_SPLINE_CMAKE_DIR}
        COMPONENT Development)
configure_package_config_file(
  ${CMAKE_CURRENT_LIST_DIR}/Triangular_splineConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/Triangular_splineConfig.cmake
  INSTALL_DESTINATION ${TRIANGULAR_SPLINE_CMAKE_DIR})
# Header-only: any architecture; versions 0.x are not compatible with each other.
write_basic_package_version_file(
  ${CMAKE_CURRENT_BINARY_DIR}/Triangular_splineConfigVersion.cmake
  COMPATIBILITY SameMinorVersion ARCH_INDEPENDENT)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/Triangular_splineConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/Triangular_splineConfigVersion.cmake
        DESTINATION ${TRIANGULAR_SPLINE_CMAKE_DIR} COMPONENT Development)

if(TARGET tspline)
  install(TARGETS tspline RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT Runtime)
endif()
