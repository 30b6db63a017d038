# Readable range checks for numeric options (synth, latency, compare).
hilrig_library(hilrig_cli_number_checks
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/number_checks.cpp
  DEPS CLI11::CLI11)
