hilrig_library(hilrig_cli_latency
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/latency_command.cpp
  DEPS hilrig_rt hilrig_cli_stop_signals hilrig_cli_number_checks CLI11::CLI11 hilrig_fmt)
