# Assets layer tests: procedural mesh builders, STL/URDF writers, and the
# generated benchmark models in assets/robot and assets/conveyor.
edgefit_add_test(assets_test
  SOURCES
    assets/mesh_builders_test.cc
    assets/stl_writer_test.cc
    assets/benchmark_assets_test.cc
  LIBS edgefit::assets edgefit::model nlohmann_json::nlohmann_json)
