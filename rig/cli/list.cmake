# `hilrig list` (owner: campaign engineer).
hilrig_library(hilrig_cli_list
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/list_command.cpp
  DEPS hilrig_campaign hilrig_duts hilrig_checks CLI11::CLI11 hilrig_fmt)
