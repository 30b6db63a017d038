hilrig_library(hilrig_cli_compare
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/compare_command.cpp
  DEPS hilrig_results hilrig_cli_number_checks CLI11::CLI11 hilrig_fmt)
