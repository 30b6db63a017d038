# `hilrig synth` (owner: signals engineer "quad"): quadrature and discrete here; other
# signal kinds add rig/cli/synth_<kind>.cpp and register themselves (synth_command.hpp).
# An OBJECT library so those self-registering objects are always linked.
file(GLOB HILRIG_CLI_SYNTH_SOURCES CONFIGURE_DEPENDS
  ${CMAKE_CURRENT_LIST_DIR}/synth_command.cpp
  ${CMAKE_CURRENT_LIST_DIR}/synth_*.cpp)
list(REMOVE_DUPLICATES HILRIG_CLI_SYNTH_SOURCES)
list(SORT HILRIG_CLI_SYNTH_SOURCES)
add_library(hilrig_cli_synth OBJECT ${HILRIG_CLI_SYNTH_SOURCES})
target_link_libraries(hilrig_cli_synth PUBLIC hilrig_flags hilrig_signals hilrig_core hilrig_cli_number_checks
  hilrig_model_ssi7361 hilrig_results CLI11::CLI11 hilrig_fmt)
