// povml fidelity scene: uv_texture
// Rule: texture { uv_mapping … } reads the rest of the block as a texture evaluated at the hit's
//       (u, v, 0): transforms inside it move its pigment, transforms after it (the texture's own,
//       the object's) do not (parstxtr.cpp, trace.cpp ComputeOneTextureColour UV_MAP_PATTERN).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0, 0> right x*image_width/image_height angle 45 }
light_source { <-4, 6, -6>, rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
#declare T = texture { uv_mapping pigment { checker rgb <1, 0.3, 0.1> rgb <0.1, 0.3, 1> } finish { ambient 0.15 diffuse 0.8 } scale <1/16, 1/8, 1> }
sphere { 0, 1 texture { T } rotate <20, 30, 0> translate <-1.2, 0, 0> }
box { -0.8, 0.8 texture { uv_mapping pigment { gradient x color_map { [0 rgb <1, 1, 0>] [1 rgb <0, 0.5, 0.3>] } scale 0.25 } } rotate y*30 translate <1.2, 0, 0> }
plane { y, -1 pigment { rgb 0.6 } }
