#!/usr/bin/env bash
# Brings the rig's CAN interfaces up at a bitrate with automatic bus-off recovery.
# Usage: can-up.sh [IFACE [BITRATE [RESTART_MS]]]   (defaults: can0 500000 100)
# For CAN FD add: dbitrate 2000000 fd on  (set HILRIG_CAN_FD=1)
set -euo pipefail
iface=${1:-can0}
bitrate=${2:-500000}
restart_ms=${3:-100}
ip link set "$iface" down 2>/dev/null || true
if [ "${HILRIG_CAN_FD:-0}" = 1 ]; then
  ip link set "$iface" type can bitrate "$bitrate" dbitrate "${HILRIG_CAN_DBITRATE:-2000000}" fd on restart-ms "$restart_ms"
else
  ip link set "$iface" type can bitrate "$bitrate" restart-ms "$restart_ms"
fi
# A deep transmit queue hides latency: keep it short so late frames show up as late.
ip link set "$iface" txqueuelen 64
ip link set "$iface" up
ip -details link show "$iface"
