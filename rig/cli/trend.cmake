# `hilrig trend` (owner: CI integration).
hilrig_library(hilrig_cli_trend
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/trend_command.cpp
  DEPS hilrig_cli_same_file hilrig_cli_run_evidence hilrig_results CLI11::CLI11 hilrig_fmt)
