// The scene of make test-slurm and make test-ssh: an animation (clock) with reflection, antialiased.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -5> look_at 0 }
light_source { <3, 5, -5>, rgb 1 }
plane { y, -1 pigment { checker rgb 1, rgb 0.2 } }
sphere { <clock, 0, 0>, 1 pigment { rgb <1, 0.5, 0.2> } finish { reflection 0.3 } }
