# same_file(): two spellings of one file, for the commands that refuse to write over an input.
hilrig_library(hilrig_cli_same_file
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/same_file.cpp)
