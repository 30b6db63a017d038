#pragma once
// The campaign the hardware tests run: the reference PLS counting a 100-line encoder at
// 150 rpm (1000 counts/s: one count a millisecond, so the edges fall on whole ms), with a
// discrete input (EN), signal faults on both encoder lines, and its output captured as ls1.
// Line numbers matter: tests point at them.

#include <string>

namespace hilrig::hardware::test {

inline const std::string kLoopCampaign = R"([campaign]
name = "loop"
end = "10ms"
[dut]
model = "reference_pls"
[dut.params]
on = 3
off = 6
filter = "200us"
[[wiring]]
rig = "enc.A"
board = "A"
[[wiring]]
rig = "enc.B"
board = "B"
[[wiring]]
rig = "en"
board = "EN"
[[wiring]]
rig = "ls1"
board = "OUT"
[encoder]
lines = 100
[motion]
[[motion.move]]
kind = "constant"
speed_rpm = 150
duration = "10ms"
[[stimulus]]
kind = "missing_edges"
at = "0ms"
line = "enc.B"
every = 2
until = "5ms"
[[stimulus]]
kind = "level"
at = "500us"
line = "en"
level = "high"
[[stimulus]]
kind = "glitch"
at = "6.5ms"
line = "enc.A"
width = "100us"
[[stimulus]]
kind = "stuck"
at = "7.5ms"
line = "enc.A"
level = "high"
until = "8.5ms"
[[check]]
kind = "throughput"
name = "on"
output = "ls1"
setpoint = 3
limit_us = 500
)";

// A rig with a GPIO line for each of the campaign's rig lines.
inline const std::string kLoopRig = R"([rt]
priority = 0
edge_tolerance = "1s"
[gpio]
chip = "gpiochip0"
[[gpio.line]]
rig = "enc.A"
offset = 0
[[gpio.line]]
rig = "enc.B"
offset = 1
[[gpio.line]]
rig = "en"
offset = 2
[[gpio.line]]
rig = "ls1"
offset = 8
)";

} // namespace hilrig::hardware::test
