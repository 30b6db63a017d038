# is_run_evidence(): the files `hilrig run` writes, shared by `run` (what it clears) and `merge`
# (what it does not write over in a run's directory).
hilrig_library(hilrig_cli_run_evidence
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/run_evidence.cpp
  DEPS hilrig_cli_directory_lock)
