// POV-Ray's shadow cache keeps, per light, one blocker for the shadow rays of camera rays' hits
// and one shared by every deeper level (Trace::TracePointLightShadowRay: the shadow ray's own
// trace level is 2 for a camera ray's hit). Inside a shiny open cup the rays bounce from wall to
// wall; a bounce's shadow ray must not try the blocker a camera ray's hit cached, whose cached
// test (hits from 1e-4 on) would find the cup's own wall.
#version 3.7;
global_settings { assumed_gamma 2.2 max_trace_level 5 }
#declare Cup =
sor {
  7,
  <0.000000, 0.000000>
  <0.118143, 0.000000>
  <0.620253, 0.540084>
  <0.210970, 0.827004>
  <0.194093, 0.962025>
  <0.286920, 1.000000>
  <0.468354, 1.033755>
  open
}
camera { location <40, 40, -80> right x*image_width/image_height angle 21 look_at <1.9, 5, 0> }
light_source { <40, 40, -80> rgb 0.4 }
light_source { <0, 50, 20> rgb 0.4 }
light_source { <50, 50, -50> rgb 0.4 }
light_source { <-50, 50, -50> rgb 0.4 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb <1, 1, 0> rgb <0.75, 1, 0> scale 5 } finish { ambient 0.2 diffuse 0.8 } }
#declare Metal = texture { pigment { rgb <0.9, 0.9, 0.95> } finish { ambient 0.25 diffuse 0.65 reflection 0.45 brilliance 1.5 specular 1 roughness 0.01 metallic } }
object { Cup texture { Metal } scale 10 translate <-15, 0.001, 15> }
object { Cup texture { Metal } scale 8 translate <0, 0.001, 15> }
object { Cup texture { Metal } scale 10 translate <15, 0.001, 15> }
object { Cup texture { Metal } scale 10 translate <-15, 0.001, -5> }
object { Cup texture { Metal } scale 9 translate <5, 0.001, -5> }
