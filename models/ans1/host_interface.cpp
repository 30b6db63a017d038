#include "models/ans1/host_interface.hpp"

#include "models/ans1/ans1.hpp"
#include "models/ans1/data_block.hpp"
#include "models/ans1/positions_fit.hpp"

namespace hilrig::models::ans1 {

HostInterface::HostInterface(Ans1& device) : device_(device) {}

void HostInterface::write(int word, std::uint16_t value) {
  commands_[static_cast<std::size_t>(word)] = value;
  device_.wake();
}

void HostInterface::write_block(const HostWords& words) {
  commands_ = words;
  device_.wake();
}

HostWords HostInterface::status() const {
  HostWords w{};
  if (!device_.powered()) return w; // [MODEL] an unpowered module answers 0
  compose_data_block(selection_, device_, active_program_, w);
  unsigned s = selection_.attribute & 0x1FU;
  if (ack_) s |= kAcknowledgeBit;
  if (device_.heartbeat()) s |= 1U << 14;
  if (hardware_fault_) s |= 1U << 13;
  if (device_.resolver_fault()) s |= 1U << 12;
  s |= error_bits(error_);
  if (device_.rpm_clamped()) s |= 1U << 7;
  if (device_.outputs_forced()) s |= 1U << 6;
  w[0] = static_cast<std::uint16_t>(s);
  return w;
}

void HostInterface::scan() {
  const bool transmit = (commands_[0] & kTransmitBit) != 0;
  if (transmit && !transmit_seen_) {
    // The block takes effect from the next scan; that scan writes the response (the data words
    // computed with the block in force) and then sets Acknowledge (L1705), so the words a host
    // reads with Acknowledge never predate the block.
    execute(commands_);
    responding_ = true;
    device_.wake(); // the responding scan must run, whatever the block changed
  } else if (!transmit) {
    ack_ = false;
    responding_ = false;
  } else if (responding_) {
    ack_ = true; // also for a rejected block [MODEL A43]
    responding_ = false;
  }
  transmit_seen_ = transmit;
}

Ans1Setup HostInterface::power_up() {
  transmit_seen_ = (commands_[0] & kTransmitBit) != 0;
  ack_ = false;
  responding_ = false;
  error_ = latched_ = ErrorCode::None;
  hardware_fault_ = false;
  selection_ = DataSelection{};
  Ans1Setup s; // factory defaults (L2236)
  if (saved_global_) {
    s.position = saved_global_->position;
    s.monitors.brake = saved_global_->monitors.brake;
  }
  const auto& p = programs_[active_program_]; // slot 0 never holds one
  if (!p) {
    // None loaded, or it was deleted (L2236): factory defaults, and no program is active (DA0
    // w17, L2338).
    active_program_ = 0;
    return s;
  }
  if (!p->checksum_ok) {
    hardware_fault_ = true; // the program read from memory fails its checksum (L2298)
    return s;
  }
  if (!positions_fit(p->setup, s.position.full_scale_count)) {
    // A position beyond the saved FSC does not run [MODEL, positions_fit.hpp]: factory
    // defaults, as after Load 40, and 1011 shows why until Clear Errors.
    active_program_ = 0;
    error_ = latched_ = ErrorCode::ParameterConflict;
    return s;
  }
  s.outputs = p->setup.outputs;
  s.shift_register = p->setup.shift_register;
  s.monitors.die = p->setup.monitors.die;
  s.monitors.production = p->setup.monitors.production;
  return s;
}

void HostInterface::corrupt_program(int slot) {
  auto& p = programs_[static_cast<std::size_t>(slot)];
  if (p) p->checksum_ok = false;
}

void HostInterface::execute(const HostWords& words) {
  const Ans1Setup current = device_.setup();
  HostContext context;
  context.active_program = active_program_;
  for (std::size_t k = 1; k < programs_.size(); ++k) {
    context.stored[k] = programs_[k] ? &programs_[k]->setup : nullptr;
  }
  const DecodedBlock d = decode_command_block(words, current, context);

  if (d.actions.clear_errors) { // L1711: programming and hardware errors
    error_ = latched_ = ErrorCode::None;
    hardware_fault_ = false;
    device_.clear_errors(); // latched resolver fault, brake overrun faults
  }
  if (d.error != ErrorCode::None) {
    error_ = d.error; // nothing applied
    if (d.error != ErrorCode::CommandWord) latched_ = d.error;
    return;
  }
  // A valid command word clears 1000 (L2305), not a code under it that needs Clear Errors
  // (1001-1100, L2306-L2309): that one shows again.
  if (error_ == ErrorCode::CommandWord) error_ = latched_;

  Ans1Setup next = d.setup;
  const BlockActions& a = d.actions;
  if (a.factory_defaults) {
    // CB2 bit 5 restores "all parameters to their default settings and erase[s] all stored
    // programming data ... cannot be restored" (L1816, L1820): the stored programs and the
    // global parameters Save Global wrote to flash (L2239) alike.
    programs_ = {};
    saved_global_.reset();
    active_program_ = 0;
    device_.force_outputs(0, 0);
    device_.force_inputs(0, 0);
  }
  run_program_command(a.program, current, next);
  apply_setup(next, current);

  if (a.selection) selection_ = *a.selection;
  if (a.output_forces) device_.force_outputs(a.output_forces->enable, a.output_forces->state);
  if (a.input_forces) device_.force_inputs(a.input_forces->enable, a.input_forces->state);
  if (a.machine_preset) device_.preset_machine();
  if (a.ls_preset_output != 0) device_.preset_output(a.ls_preset_output);
  if (a.counter_preset) device_.preset_counter(a.counter_preset->counter, a.counter_preset->value);
}

void HostInterface::run_program_command(const ProgramCommand& cmd, const Ans1Setup& current,
                                        Ans1Setup& next) {
  if (cmd.delete_stored) programs_ = {};
  if (cmd.save_global) saved_global_ = current; // only its position and brake parts count
  if (cmd.save_program) {
    const std::uint8_t slot = cmd.slot == 0 ? active_program_ : cmd.slot;
    programs_[slot] = StoredProgram{current, true};
    active_program_ = slot;
  }
  if (!cmd.load_program || cmd.slot == 0) return; // slot 0: the active program, nothing to do
  if (cmd.slot == kFactoryProgram) {
    next = Ans1Setup{}; // factory defaults in RAM; stored programs stay (L2245)
    active_program_ = 0;
    return;
  }
  const StoredProgram& p = *programs_[cmd.slot];
  if (!p.checksum_ok) {
    hardware_fault_ = true; // checksum error in the program read from memory (L2298)
    return;
  }
  // A program is everything but the global parameters (CB2, CB8), which Save Global keeps.
  next.outputs = p.setup.outputs;
  next.shift_register = p.setup.shift_register;
  next.monitors.die = p.setup.monitors.die;
  next.monitors.production = p.setup.monitors.production;
  active_program_ = cmd.slot;
}

void HostInterface::apply_setup(const Ans1Setup& next, const Ans1Setup& current) {
  if (!(next.position == current.position)) device_.configure_position(next.position);
  for (int n = 1; n <= kOutputCount; ++n) {
    if (!(next.output(n) == current.output(n))) device_.configure_output(n, next.output(n));
  }
  if (!(next.shift_register == current.shift_register)) device_.configure_shift_register(next.shift_register);
  if (!(next.monitors == current.monitors)) device_.configure_monitors(next.monitors);
}

} // namespace hilrig::models::ans1
