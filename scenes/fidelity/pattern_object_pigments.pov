// povml fidelity scene: pattern_object_pigments
// Rule: object pattern with two pigments listed inside its block (evaluated at the same
// pattern-space point), the pattern itself rotated and scaled after the block (the point moves,
// the object stays as parsed), an inverted object and an identifier with a texture of its own.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -4> look_at <0, 0.5, 0> angle 60 }
#declare S = sphere { <0.5, 0, 0>, 1.1 texture { pigment { rgb 1 } } }
plane { y, 0
  pigment {
    object { S
      pigment { checker rgb <0.1, 0, 0.4>, rgb <0, 0.7, 0.2> scale 0.25 }
      pigment { gradient x color_map { [0 rgb <1, 0.8, 0>] [1 rgb <1, 0.1, 0.1>] } }
    }
    rotate <0, 40, 0> scale <1.5, 1, 1>
  }
  finish { ambient 1 diffuse 0 } }
sphere { <0, 1, 0>, 1
  pigment { object { box { <-0.5, 0.6, -2>, <0.4, 1.3, 2> inverse } pigment { rgb <0, 0.7, 0.2> }, pigment { bozo scale 0.2 } } }
  finish { ambient 1 diffuse 0 } }
