# cmake --install: headers, static libraries, the CLI and wrenchkit-check, the Python package (python/),
# and the CMake package wrenchkitConfig.cmake so that consumers write
#   find_package(wrenchkit REQUIRED)  target_link_libraries(app PRIVATE wrenchkit::exact)
# (docs/cmake-package.md; tests/consumer/ proves it in CTest); find_package(wrenchkit COMPONENTS cgal) adds
# wrenchkit::cgal, the CGAL face of the exact API. Included from the top-level CMakeLists.txt.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# Headers under <prefix>/include/wrenchkit/{core,exact,float,proofs/checker}; that directory is on the
# targets' include path, so the repository's includes ("exact/statics/closure.h") work unchanged, and
# <prefix>/include is too, for "wrenchkit/exact/closure.h".
set(WRENCHKIT_INSTALL_INCLUDEDIR "${CMAKE_INSTALL_INCLUDEDIR}/wrenchkit")
set(WRENCHKIT_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/wrenchkit")

set_target_properties(wrenchkit_core PROPERTIES EXPORT_NAME core)
set_target_properties(wrenchkit_float PROPERTIES EXPORT_NAME float)
set_target_properties(wrenchkit_exact PROPERTIES EXPORT_NAME exact)
# The engine's parts (docs/design.md, "The parts and their walls"), which wrenchkit::exact links together.
foreach(part numbers io statics sliding fixture certificates)
  set_target_properties(wrenchkit_${part} PROPERTIES EXPORT_NAME ${part})
endforeach()
set_target_properties(wrenchkit_pipeline PROPERTIES EXPORT_NAME pipeline)
set_target_properties(wrenchkit_checker PROPERTIES EXPORT_NAME checker)
set_target_properties(wrenchkit_gmp PROPERTIES EXPORT_NAME gmp)
# Static libraries that a shared library (a consumer's plugin, the Python module) may link.
# -fno-semantic-interposition keeps GCC inlining within a library as without -fPIC.
foreach(t wrenchkit_float wrenchkit_numbers wrenchkit_io wrenchkit_statics wrenchkit_sliding wrenchkit_fixture wrenchkit_certificates
          wrenchkit_pipeline wrenchkit_checker wrenchkit_cgal wrenchkit_mesh_io)
  set_property(TARGET ${t} PROPERTY POSITION_INDEPENDENT_CODE ON)
  target_compile_options(${t} PRIVATE -fno-semantic-interposition)
endforeach()
target_include_directories(wrenchkit_core INTERFACE
  "$<INSTALL_INTERFACE:${WRENCHKIT_INSTALL_INCLUDEDIR}>" "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
target_include_directories(wrenchkit_checker INTERFACE "$<INSTALL_INTERFACE:${WRENCHKIT_INSTALL_INCLUDEDIR}>")

install(TARGETS wrenchkit_core wrenchkit_float wrenchkit_numbers wrenchkit_io wrenchkit_statics wrenchkit_sliding
  wrenchkit_fixture wrenchkit_certificates wrenchkit_exact wrenchkit_pipeline wrenchkit_gmp wrenchkit_checker
  EXPORT wrenchkitTargets
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT development)
# The CGAL face (exact/cgal/cgal.h) and the mesh writers: their own export set, loaded only by
# find_package(wrenchkit COMPONENTS cgal) (or when CGAL is found), so the other components never need CGAL.
set_target_properties(wrenchkit_cgal PROPERTIES EXPORT_NAME cgal)
set_target_properties(wrenchkit_mesh_io PROPERTIES EXPORT_NAME mesh_io)
install(TARGETS wrenchkit_cgal wrenchkit_mesh_io EXPORT wrenchkitCGALTargets
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT development)
install(EXPORT wrenchkitCGALTargets NAMESPACE wrenchkit:: DESTINATION "${WRENCHKIT_INSTALL_CMAKEDIR}"
  COMPONENT development)
install(TARGETS wrenchkit wrenchkit-check RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}" COMPONENT runtime)
# The reference that the CLI's help texts and JSON "convention" strings cite as "theory.md §x".
install(FILES "${PROJECT_SOURCE_DIR}/docs/theory.md" "${PROJECT_SOURCE_DIR}/docs/theory-sliding.md"
  DESTINATION "${CMAKE_INSTALL_DOCDIR}" COMPONENT runtime)
foreach(dir core exact float)
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/${dir}/" DESTINATION "${WRENCHKIT_INSTALL_INCLUDEDIR}/${dir}"
    COMPONENT development FILES_MATCHING PATTERN "*.h")
endforeach()
install(FILES "${PROJECT_SOURCE_DIR}/proofs/checker/checker.h"
  DESTINATION "${WRENCHKIT_INSTALL_INCLUDEDIR}/proofs/checker" COMPONENT development)

install(EXPORT wrenchkitTargets NAMESPACE wrenchkit:: DESTINATION "${WRENCHKIT_INSTALL_CMAKEDIR}"
  COMPONENT development)
configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/wrenchkitConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/cmake/wrenchkitConfig.cmake"
  INSTALL_DESTINATION "${WRENCHKIT_INSTALL_CMAKEDIR}"
  PATH_VARS WRENCHKIT_INSTALL_INCLUDEDIR)
# 0.x: a minor version may change the API.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/cmake/wrenchkitConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/cmake/wrenchkitConfig.cmake"
  "${PROJECT_BINARY_DIR}/cmake/wrenchkitConfigVersion.cmake" "${PROJECT_SOURCE_DIR}/cmake/wrenchkitGMP.cmake"
  DESTINATION "${WRENCHKIT_INSTALL_CMAKEDIR}" COMPONENT development)
