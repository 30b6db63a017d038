# DirectoryLock: DIR/.hilrig.lock, shared by `run` (its --out) and `merge` (writing into a run's directory).
hilrig_library(hilrig_cli_directory_lock
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/directory_lock.cpp
  DEPS hilrig_fmt)
