# Usage hints for the hilrig command line: unknown subcommands and options, with the closest names.
hilrig_library(hilrig_cli_usage
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/usage_hints.cpp
  DEPS hilrig_core CLI11::CLI11 hilrig_fmt)
