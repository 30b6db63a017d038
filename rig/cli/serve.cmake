hilrig_library(hilrig_cli_serve
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/serve_command.cpp
  DEPS hilrig_model_smd23e hilrig_drivers_modbus CLI11::CLI11)
