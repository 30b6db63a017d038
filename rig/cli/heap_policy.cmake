# The allocator policy of `hilrig run` (freed heap kept for the next run).
hilrig_library(hilrig_cli_heap_policy
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/heap_policy.cpp)
