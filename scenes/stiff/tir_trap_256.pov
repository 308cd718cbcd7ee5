// povml stiff scene: tir_trap_256
// Stresses: tir_trap.pov at POV-Ray's largest max_trace_level, 256: trapped rays recurse 256
// levels deep through refraction calls. POV-Ray 3.7.0.10 crashes on it (its 4 MB render-thread
// stack overflows from level 218 on, see tir_trap.pov), so it has no POV-Ray reference; povml
// must render it without a stack overflow, the same image as tir_trap.pov except that rays
// trapped for more than 200 levels pick up a little more glass tint.
#version 3.7;
#declare Trap_level = 256;
#include "tir_trap.pov"
