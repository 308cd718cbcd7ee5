// Fuzz seed: directives, macros and nesting (docs/povray-rules.md §11.3).
#version 3.7;
#default { finish { ambient 0.2 diffuse 0.7 } }
global_settings { assumed_gamma 2.2 max_trace_level 8 adc_bailout 0.01 ambient_light rgb 0.5 }
background { rgb <0.1, 0.2, 0.3> }
sky_sphere { pigment { rgb <0.2, 0.3, 0.9> } }
#declare Tex = texture { pigment { rgb y } };
#macro Twice(X) (2 * X) #end
#macro Put(P, R) sphere { P, R pigment { rgbt <1, 0.5, 0, 0.3> } } #end
#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end
#local I = 0;
#while (1)
  #if (I > 3) #break #elseif (I = 2) #warning "two" #else #end
  #local I = I + 1;
#end
#for (J, 0, Twice(1), 0.5)
  #switch (J)
    #case (0) Put(<J, 0, 0>, 0.3) #break
    #range (0.5, 1.5) #declare K = J;
    #else #ifdef (K) #undef K #end
  #end
#end
#ifndef (K) #declare K = Fact(5); #end
union {
  object { Put(<0, 1, 0>, 0.5) translate <1, 0, 0> }
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  smooth_triangle { <0, 0, 1>, y, <1, 0, 1>, y, <0, 1, 1>, z }
  mesh2 {
    vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <0, 1, 0>, <1, 1, 0> }
    normal_vectors { 1, z }
    texture_list { 2, texture { pigment { rgb 1 } }, texture { pigment { rgb x } } }
    face_indices { 2, <0, 1, 2>, 0, <1, 3, 2>, 1 }
    normal_indices { 2, <0, 0, 0>, <0, 0, 0> }
    inside_vector z
  }
  mesh { triangle { 0, x, y texture { Tex } } inside_vector x }
  plane { -y, 1 hollow no_shadow }
  texture { pigment { rgb <1, 1, 0> } finish { phong 0.5 phong_size 40 reflection { 0.1, 0.5 fresnel on falloff 2 exponent 1 metallic 0.5 } conserve_energy } }
  interior { ior 1.5 fade_distance 1 fade_power 2 fade_color rgb <1, 0, 0> }
  translate <0, K / 1000, 0>
}
camera { perspective location <0, 2, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-3, 5, -4>, rgb 1 }
