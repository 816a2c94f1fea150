# Installation and the CMake package, as small_gicp does it: the targets in an export set under
# the namespace pagor::, a config file that finds the dependencies again (find_dependency), and a
# version file. After `cmake --install build --prefix P`, a project that sets
# CMAKE_PREFIX_PATH=P writes
#   find_package(pagor REQUIRED)
#   target_link_libraries(app PRIVATE pagor::core)      # + pagor::eval for the harness
# and includes <pagor/pagor.hpp> (<pagor/eval/eval.hpp>); Eigen, PCL and nlohmann-json come with
# pagor::core.
#
#   include/pagor/...              the public headers (core/include; never core/src)
#   lib/libpagor_core.a            the libraries (static unless BUILD_SHARED_LIBS), and
#   lib/libpagor_eval.a            the evaluation harness
#   lib/cmake/pagor/               pagorConfig.cmake, pagorConfigVersion.cmake, pagorTargets*.cmake
#   bin/pagor, bin/pagor-studio    the tools (when built)
# The Python module is installed by pip (pyproject.toml, setup.py), not here.
include(CMakePackageConfigHelpers)

set(PAGOR_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/pagor)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/core/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(TARGETS pagor_core pagor_eval EXPORT pagorTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET pagor)
  install(TARGETS pagor RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
if(TARGET pagor-studio)
  install(TARGETS pagor-studio RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

install(EXPORT pagorTargets NAMESPACE pagor:: DESTINATION ${PAGOR_CMAKE_INSTALL_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/pagorConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/pagorConfig.cmake
                              INSTALL_DESTINATION ${PAGOR_CMAKE_INSTALL_DIR})
# 0.x: a minor version may break the API, so only the same minor version is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/pagorConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/pagorConfig.cmake ${PROJECT_BINARY_DIR}/pagorConfigVersion.cmake
        DESTINATION ${PAGOR_CMAKE_INSTALL_DIR})
