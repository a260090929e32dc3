# Tests of gsp::core's mesh pieces: topology report, welding, cache layout. Tiny meshes are
# built in code (helpers/mesh_builders.hpp); the shared-data test also needs the readers.
gsp_test(core_topology SOURCES core_topology.cpp DEPS gsp::core)
gsp_test(core_weld SOURCES core_weld.cpp DEPS gsp::core)
