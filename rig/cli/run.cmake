# `hilrig run` (owner: campaign engineer).
hilrig_library(hilrig_cli_run
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/run_command.cpp
    ${CMAKE_CURRENT_LIST_DIR}/output_dir.cpp
    ${CMAKE_CURRENT_LIST_DIR}/run_progress.cpp
    ${CMAKE_CURRENT_LIST_DIR}/suite_files.cpp
    ${CMAKE_CURRENT_LIST_DIR}/wall_clock.cpp
    ${CMAKE_CURRENT_LIST_DIR}/trace_files.cpp
  DEPS hilrig_cli_directory_lock hilrig_cli_run_evidence hilrig_cli_seed hilrig_cli_stop_signals hilrig_cli_heap_policy hilrig_campaign hilrig_results hilrig_cli_serve hilrig_hardware CLI11::CLI11 hilrig_fmt Boost::boost Threads::Threads)
