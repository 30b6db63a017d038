# --seed, one parser for every command that takes one (run, power).
hilrig_library(hilrig_cli_seed
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/seed_option.cpp
  DEPS CLI11::CLI11 hilrig_fmt)
