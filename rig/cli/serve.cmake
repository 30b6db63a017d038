# `hilrig serve DEVICE`: the device table (serve_devices.cpp) names every model it links.
hilrig_library(hilrig_cli_serve
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/serve_command.cpp
    ${CMAKE_CURRENT_LIST_DIR}/serve_controls.cpp
    ${CMAKE_CURRENT_LIST_DIR}/serve_devices.cpp
    ${CMAKE_CURRENT_LIST_DIR}/serve_far_side.cpp
    ${CMAKE_CURRENT_LIST_DIR}/serve_params.cpp
  DEPS hilrig_model_smd23e hilrig_model_ans1 hilrig_model_amci4501 hilrig_model_ssi7361 hilrig_model_pls2700 hilrig_drivers_virtual
       hilrig_drivers_modbus hilrig_far hilrig_cli_stop_signals hilrig_campaign hilrig_duts hilrig_signals CLI11::CLI11 hilrig_fmt)
