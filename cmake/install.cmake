# Install rules and the CMake package (included at the end of the top-level CMakeLists.txt).
#
#   cmake --install build --prefix P
# gives P/include/exactvis/<module>/*.hpp (the source layout, so installed headers include each other as in
# the tree), P/lib/libexactvis_<module>.a, P/bin/exactvis and P/lib/cmake/exactvis/ with
#   find_package(exactvis CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE exactvis::exactvis)   # or exactvis::region, exactvis::events, ...
# The dependencies (CGAL, oneTBB, GLM, Embree, OpenMesh, VTK, nlohmann-json) are found again by
# exactvis-config.cmake (find_dependency), so they reach the user's targets transitively.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(EXACTVIS_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/exactvis)

# api/version.hpp (EXACTVIS_VERSION), generated from project(exactvis VERSION ...).
configure_file(${PROJECT_SOURCE_DIR}/cmake/version.hpp.in ${PROJECT_BINARY_DIR}/generated/api/version.hpp @ONLY)
target_include_directories(exactvis_api PUBLIC $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/generated>)
install(FILES ${PROJECT_BINARY_DIR}/generated/api/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/exactvis/api)

# exactvis::exactvis: every module library.
add_library(exactvis_exactvis INTERFACE)
target_link_libraries(exactvis_exactvis INTERFACE ${EXACTVIS_MODULE_TARGETS})
set_target_properties(exactvis_exactvis PROPERTIES EXPORT_NAME exactvis)
add_library(exactvis::exactvis ALIAS exactvis_exactvis)

foreach(module ${EXACTVIS_MODULES})
  if(TARGET exactvis_${module})
    set_target_properties(exactvis_${module} PROPERTIES EXPORT_NAME ${module})
    add_library(exactvis::${module} ALIAS exactvis_${module})
    install(TARGETS exactvis_${module} EXPORT exactvisTargets
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  endif()
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${module}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/exactvis/${module}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
install(TARGETS exactvis_exactvis EXPORT exactvisTargets)
install(TARGETS exactvis RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

install(EXPORT exactvisTargets NAMESPACE exactvis:: DESTINATION ${EXACTVIS_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/exactvis-config.cmake.in
                              ${PROJECT_BINARY_DIR}/exactvis-config.cmake INSTALL_DESTINATION ${EXACTVIS_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/exactvis-config-version.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/exactvis-config.cmake ${PROJECT_BINARY_DIR}/exactvis-config-version.cmake
        DESTINATION ${EXACTVIS_INSTALL_CMAKEDIR})
