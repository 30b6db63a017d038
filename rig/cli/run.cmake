# `hilrig run` (owner: campaign engineer).
hilrig_library(hilrig_cli_run
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/run_command.cpp
  DEPS hilrig_campaign hilrig_results CLI11::CLI11 fmt::fmt)
