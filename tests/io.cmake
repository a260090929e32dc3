# Tests of gsp::io: golden counts on the shared meshes, one fixture per format feature
# (tests/data/io), round trips through every writer, a corpus of broken files, atomic output
# and colour maps.
gsp_test(io_shared_meshes SOURCES io_shared_meshes.cpp DEPS gsp::io)
gsp_test(io_read_fixtures SOURCES io_read_fixtures.cpp DEPS gsp::io)
gsp_test(io_broken_files SOURCES io_broken_files.cpp DEPS gsp::io)
gsp_test(io_round_trip SOURCES io_round_trip.cpp DEPS gsp::io)
gsp_test(io_atomic_file SOURCES io_atomic_file.cpp DEPS gsp::io)
gsp_test(io_colormap SOURCES io_colormap.cpp DEPS gsp::io)
gsp_test(io_parallel_read SOURCES io_parallel_read.cpp DEPS gsp::io)
