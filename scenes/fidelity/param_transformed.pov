// povml fidelity scene: param_transformed
// Rule: a parametric surface moved by rotate, scale (non-uniform) and translate, composed into
//       its transform: the ray taken into its space unnormalised, the normal through the
//       inverse transpose; uv_mapping sees the (u, v) of the piece found (its lower corner);
//       a bumpy normal and a second, patterned texture.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -4.5> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
#declare Torus = parametric {
  function { cos(u)*(1 + 0.35*cos(v)) },
  function { 0.35*sin(v) },
  function { sin(u)*(1 + 0.35*cos(v)) }
  <0, 0>, <2*pi, 2*pi>
  contained_by { box { <-1.4, -0.4, -1.4>, <1.4, 0.4, 1.4> } }
  accuracy 0.003
}
object { Torus
  texture { uv_mapping pigment { checker rgb <0.9, 0.2, 0.2> rgb <0.95, 0.95, 0.9> scale <pi/6, pi/3, 1> } finish { phong 0.6 } }
  rotate <50, 0, 20> scale <0.8, 1.2, 0.7> translate <-0.9, 0.3, 0>
}
object { Torus
  texture { pigment { gradient y colour_map { [0 rgb <0.2, 0.4, 0.9>] [1 rgb <0.9, 0.9, 0.3>] } scale 0.5 }
            normal { bumps 0.4 scale 0.1 } finish { specular 0.5 } }
  scale 0.6 rotate <-70, 30, 0> translate <1.1, 0.1, 0.3>
}
plane { y, -1 pigment { rgb <0.8, 0.8, 0.75> } }
