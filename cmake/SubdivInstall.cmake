# Install rules (SUBDIV_INSTALL): the library, its public headers with the
# generated version.h, the subdiv program when built, the docs and licence,
# a CMake package (find_package(subdiv CONFIG), target subdiv::subdiv) and
# subdiv.pc for pkg-config.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SUBDIV_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/subdiv)

install(TARGETS subdiv_lib EXPORT subdivTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/subdiv ${PROJECT_BINARY_DIR}/include/subdiv
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(TARGET subdiv)
  install(TARGETS subdiv RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/CHANGELOG.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})

install(EXPORT subdivTargets NAMESPACE subdiv:: DESTINATION ${SUBDIV_CMAKE_DIR})
# A static library passes TBB, {fmt} and TinyGLTF on to the final link, so the package
# looks for them too; a shared one needs only what the headers include.
if(BUILD_SHARED_LIBS)
  set(SUBDIV_PRIVATE_DEPENDENCIES "")
else()
  set(SUBDIV_PRIVATE_DEPENDENCIES "find_dependency(TBB)\nfind_dependency(fmt)\nfind_dependency(TinyGLTF CONFIG)")
endif()
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/subdivConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/subdivConfig.cmake INSTALL_DESTINATION ${SUBDIV_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/subdivConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/subdivConfig.cmake ${PROJECT_BINARY_DIR}/subdivConfigVersion.cmake
        DESTINATION ${SUBDIV_CMAKE_DIR})

# pkg-config: Eigen's flags come from its own eigen3.pc; a static library
# also names TBB, {fmt} and TinyGLTF for the final link.
if(BUILD_SHARED_LIBS)
  set(SUBDIV_PC_REQUIRES_PRIVATE "")
  set(SUBDIV_PC_LIBS_PRIVATE "")
else()
  set(SUBDIV_PC_REQUIRES_PRIVATE "tbb fmt tinygltf")
  set(SUBDIV_PC_LIBS_PRIVATE "-lstdc++")
endif()
# The prefix, relative to the .pc file, so that an installed tree can move.
string(REGEX REPLACE "[^/]+" ".." SUBDIV_PC_TO_PREFIX "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
configure_file(${PROJECT_SOURCE_DIR}/cmake/subdiv.pc.in ${PROJECT_BINARY_DIR}/subdiv.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/subdiv.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
