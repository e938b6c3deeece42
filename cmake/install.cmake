# `cmake --install`: the static libraries, the public headers (include/raycast/ only), the CMake
# package (find_package(raycast) -> raycast::raycast) and a pkg-config file. docs/library.md.

# Every library target of the engine's layers (whatever layers exist), plus the public API.
get_property(layer_targets DIRECTORY ${PROJECT_SOURCE_DIR}/src/raycast PROPERTY BUILDSYSTEM_TARGETS)
set(raycast_install_targets raycast raycast_options)
set(raycast_pc_libs "")
foreach(t ${layer_targets})
  get_target_property(type ${t} TYPE)
  if(t MATCHES "^raycast_" AND (type STREQUAL "STATIC_LIBRARY" OR type STREQUAL "INTERFACE_LIBRARY"))
    list(APPEND raycast_install_targets ${t})
  endif()
endforeach()
# Link order for pkg-config: higher layers first. A static layer missing here stops the
# configure, so that a new layer cannot leave the pkg-config link incomplete.
set(raycast_pc_order api cast render load pov scene texture objects mesh csg volume accel geometry io math)
foreach(layer ${raycast_pc_order})
  if(TARGET raycast_${layer})
    get_target_property(type raycast_${layer} TYPE)
    if(type STREQUAL "STATIC_LIBRARY")
      string(APPEND raycast_pc_libs " -lraycast_${layer}")
      string(STRIP "${raycast_pc_libs}" raycast_pc_libs)
    endif()
  endif()
endforeach()
foreach(t ${layer_targets})
  get_target_property(type ${t} TYPE)
  string(REGEX REPLACE "^raycast_" "" layer "${t}")
  if(type STREQUAL "STATIC_LIBRARY" AND NOT layer IN_LIST raycast_pc_order)
    message(FATAL_ERROR "cmake/install.cmake: put the layer '${layer}' in raycast_pc_order")
  endif()
endforeach()

install(TARGETS ${raycast_install_targets} EXPORT raycastTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/raycast DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_BINARY_DIR}/include/raycast/version.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/raycast)

set(raycast_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/raycast)
install(EXPORT raycastTargets NAMESPACE raycast:: DESTINATION ${raycast_cmake_dir})

# The config finds what the static libraries link against.
set(raycast_deps "list(APPEND CMAKE_MODULE_PATH \${CMAKE_CURRENT_LIST_DIR})
find_dependency(yaml-cpp)\nfind_dependency(LibYAML)\nfind_dependency(TBB)\nfind_dependency(PNG)\nfind_dependency(Freetype)\n")
# OpenVDB, assimp and OpenEXR are used through plugins (lib/raycast/libraycast_*.so), loaded at
# run time: users link nothing of them.
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/raycastConfig.cmake.in
  ${PROJECT_BINARY_DIR}/raycastConfig.cmake INSTALL_DESTINATION ${raycast_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/raycastConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/raycastConfig.cmake
  ${PROJECT_BINARY_DIR}/raycastConfigVersion.cmake ${PROJECT_SOURCE_DIR}/cmake/FindLibYAML.cmake
  DESTINATION ${raycast_cmake_dir})

set(raycast_pc_requires "yaml-cpp yaml-0.1 tbb libpng freetype2")
set(raycast_pc_extra "")
foreach(lib ${CMAKE_DL_LIBS})  # the plugin loader (io/plugin_library.cpp)
  string(APPEND raycast_pc_extra " -l${lib}")
endforeach()
configure_file(${PROJECT_SOURCE_DIR}/cmake/raycast.pc.in ${PROJECT_BINARY_DIR}/raycast.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/raycast.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
