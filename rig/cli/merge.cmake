hilrig_library(hilrig_cli_merge
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/merge_command.cpp
  DEPS hilrig_cli_directory_lock hilrig_cli_run_evidence hilrig_cli_same_file hilrig_results CLI11::CLI11 hilrig_fmt)
