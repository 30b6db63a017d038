# `hilrig power`: each check's detection power on the virtual board (rig/power).
hilrig_library(hilrig_cli_power
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/power_command.cpp
  DEPS hilrig_cli_seed hilrig_power hilrig_campaign hilrig_results CLI11::CLI11 hilrig_fmt)
