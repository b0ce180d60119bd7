# The modeling workloads' peer adapters (decimation and remeshing with
# OpenMesh and CGAL, bench/modeling/modeling_peers.h), each compiled once and
# linked into both bench_modeling and cgogn_modeling_peer_tests. Included by
# whichever of bench/ and tests/modeling/ is configured first; each adapter is
# an object library so that the peers' usage requirements (CGAL adds
# -frounding-math) stay on its own translation unit.
#   cgogn_peer_modeling_openmesh, when OpenMesh is found
#   cgogn_peer_modeling_cgal, when CGAL is found
include_guard(GLOBAL)
find_package(OpenMesh QUIET CONFIG)
set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE CACHE INTERNAL "the peers only serve benchmarks and cross-checks")
find_package(CGAL QUIET CONFIG)
set(_peers_dir ${CMAKE_CURRENT_LIST_DIR})
if(TARGET OpenMeshCore)
  add_library(cgogn_peer_modeling_openmesh OBJECT EXCLUDE_FROM_ALL ${_peers_dir}/modeling_openmesh.cpp)
  target_link_libraries(cgogn_peer_modeling_openmesh PRIVATE OpenMeshCore OpenMeshTools)
  target_include_directories(cgogn_peer_modeling_openmesh PRIVATE ${_peers_dir}/../modeling)
  # peer headers are not ours: SYSTEM, so that -Werror stays about our code
  get_target_property(_om_inc OpenMeshCore INTERFACE_INCLUDE_DIRECTORIES)
  if(_om_inc)
    target_include_directories(cgogn_peer_modeling_openmesh SYSTEM PRIVATE ${_om_inc})
  endif()
  target_compile_definitions(cgogn_peer_modeling_openmesh PRIVATE _USE_MATH_DEFINES)
  cgogn_set_warnings(cgogn_peer_modeling_openmesh)
  # OpenMesh default-constructs its vectors uninitialized: GCC flags their copies
  target_compile_options(cgogn_peer_modeling_openmesh PRIVATE $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)
endif()
if(CGAL_FOUND)
  add_library(cgogn_peer_modeling_cgal OBJECT EXCLUDE_FROM_ALL ${_peers_dir}/modeling_cgal.cpp)
  # the Garland-Heckbert policies solve their quadrics with Eigen
  target_link_libraries(cgogn_peer_modeling_cgal PRIVATE CGAL::CGAL Eigen3::Eigen)
  target_include_directories(cgogn_peer_modeling_cgal PRIVATE ${_peers_dir}/../modeling)
  target_compile_definitions(cgogn_peer_modeling_cgal PRIVATE CGAL_EIGEN3_ENABLED)
  get_target_property(_cgal_inc CGAL::CGAL INTERFACE_INCLUDE_DIRECTORIES)
  if(_cgal_inc)
    target_include_directories(cgogn_peer_modeling_cgal SYSTEM PRIVATE ${_cgal_inc})
  endif()
  cgogn_set_warnings(cgogn_peer_modeling_cgal)
  # CGAL copies default-constructed (uninitialized) Eigen matrices: GCC flags the copies
  target_compile_options(cgogn_peer_modeling_cgal PRIVATE $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)
endif()
