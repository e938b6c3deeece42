# OpenVDB float grids as iso-surface input (docs/iso-surfaces.md): optional like Embree. The option
# is on when Debian's libopenvdb-dev (with libboost-dev, whose headers OpenVDB's include) is found;
# it defines the imported target raycast::openvdb, which volume/ links.
find_path(RAYCAST_OPENVDB_INCLUDE_DIR openvdb/openvdb.h)
find_path(RAYCAST_BOOST_INCLUDE_DIR boost/numeric/conversion/conversion_traits.hpp)
find_library(RAYCAST_OPENVDB_LIBRARY openvdb)
find_library(RAYCAST_IMATH_LIBRARY NAMES Imath Imath-3_1)
set(raycast_openvdb_found OFF)
if(RAYCAST_OPENVDB_INCLUDE_DIR AND RAYCAST_BOOST_INCLUDE_DIR AND RAYCAST_OPENVDB_LIBRARY
   AND RAYCAST_IMATH_LIBRARY)
  set(raycast_openvdb_found ON)
endif()
option(RAYCAST_OPENVDB "Read OpenVDB grids (needs libopenvdb-dev and libboost-dev)"
  ${raycast_openvdb_found})
if(RAYCAST_OPENVDB)
  if(NOT raycast_openvdb_found)
    message(FATAL_ERROR "RAYCAST_OPENVDB is on but OpenVDB was not found "
      "(apt-get install libopenvdb-dev libboost-dev, or -DRAYCAST_OPENVDB=OFF)")
  endif()
  add_library(raycast::openvdb INTERFACE IMPORTED)
  set_target_properties(raycast::openvdb PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${RAYCAST_OPENVDB_INCLUDE_DIR};${RAYCAST_BOOST_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${RAYCAST_OPENVDB_LIBRARY};${RAYCAST_IMATH_LIBRARY};TBB::tbb")
endif()
message(STATUS "raycast: OpenVDB grids ${RAYCAST_OPENVDB}")
