# `hilrig check`: campaign files validated as `hilrig run` reads them, nothing run.
hilrig_library(hilrig_cli_check
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/check_command.cpp
  DEPS hilrig_cli_run hilrig_campaign CLI11::CLI11 hilrig_fmt)
