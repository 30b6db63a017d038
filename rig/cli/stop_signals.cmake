# SIGINT/SIGTERM as a stop request (StopSignals): shared by `run`, `serve` and `latency`.
hilrig_library(hilrig_cli_stop_signals
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/stop_signals.cpp)
