// povml fidelity scene: blob_many
// Rule: a blob of 41 components (random spheres, some negative, cylinders, one ellipsoid) goes
//       through POV-Ray's bounding sphere hierarchy (bsphere.cpp: sorted along the widest axis
//       with glibc's merge sort, split by the least count × squared-radius sum, 4 per node),
//       whose visiting order decides the order of the interval list and of the field and
//       normal sums; sturm solves the intervals' quartics with Sturm sequences. A checkered
//       floor seen in its reflection, shadows from two lights.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 0, 0> right x*image_width/image_height }
light_source { <-5, 8, -6>, rgb 1 }
light_source { <5, 2, -6>, rgb 0.4 }
background { rgb <0.2,0.3,0.4> }
#declare R = seed(3);
blob { threshold 0.55
  #declare I = 0;
  #while (I < 40)
    #if (rand(R) < 0.7)
      sphere { <-3+6*rand(R), -1.5+3*rand(R), -1+2*rand(R)>, 0.5+0.8*rand(R), (rand(R) < 0.85 ? 1 : -1.2) }
    #else
      cylinder { <-3+6*rand(R), -1.5+3*rand(R), -1+2*rand(R)>, <-3+6*rand(R), -1.5+3*rand(R), -1+2*rand(R)>, 0.2+0.4*rand(R), 1 }
    #end
    #declare I = I + 1;
  #end
  sphere { 0, 1, 1 scale <2, 0.5, 1> rotate z*20 translate <1, 1, -1> }
  pigment { rgb <0.9, 0.6, 0.3> } finish { phong 0.6 specular 0.3 reflection 0.1 }
  rotate y*10 sturm }
plane { y, -2 pigment { checker rgb 0.3 rgb 0.9 } }
