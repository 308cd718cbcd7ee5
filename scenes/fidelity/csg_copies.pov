// povml fidelity scene: csg_copies
// Rule: object { CSG_Id modifiers } is a deep copy: an added pigment belongs to the CSG node, so the
//       member with its own pigment keeps it and the others take the new one (§19.3, §16.5);
//       inverse on a copy of a difference morphs it into a merge (§16.3), here clipped to a
//       window by an intersection. A glass CSG with interior fade shared by its members: the
//       fade applies across the members (§6.3) and in the shadows (fade_power > 0, §4).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0, 3, -7> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.25, 0.3, 0.45> }
light_source { <-3, 8, -5>, rgb 1 }
#declare U = union {
  sphere { <0, 0.5, 0>, 0.5 pigment { rgb <0.9, 0.8, 0.1> } }
  sphere { <0, 1.2, 0>, 0.35 }
  split_union off
}
object { U pigment { rgb <0, 1, 1> } translate <-2.5, 0, 0> }
object { U translate <-1.5, 0, 0> }
#declare D = difference { box { -0.5, 0.5 } sphere { <0, 0, -0.5>, 0.4 } }
intersection {
  object { D inverse }
  box { <-0.7, -0.7, -0.7>, <0.7, 0.7, 0.7> }
  pigment { rgb <0.8, 0.3, 0.6> }
  rotate y*-30
  translate <0, 0.7, 0>
}
merge {
  box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> }
  sphere { <0, 1, 0>, 0.5 }
  pigment { rgbf <0.8, 1, 0.8, 0.9> } finish { ambient 0 diffuse 0.1 phong 0.7 }
  interior { ior 1.3 fade_distance 0.8 fade_power 2 fade_colour <0.2, 0.6, 0.2> }
  translate <1.9, 0, 0>
}
box { <-4, 0, 2>, <4, 3, 2.2> pigment { rgb <0.9, 0.9, 0.9> } }
plane { y, 0 pigment { rgb <0.75, 0.75, 0.7> } }
