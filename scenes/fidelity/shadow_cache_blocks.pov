// POV-Ray's shadow cache (the object that last blocked each light) belongs to its render thread
// and carries from one block to the next: rendered with one thread (+WT1), a block's first
// shadow tests try the object the previous block left in the cache. Where the cached object's
// own test and the full search disagree by a tolerance (here a height field seen from far),
// a pixel shows it. One rule: the cache is not emptied between blocks.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <-150, 300, -650> angle 20 right x*image_width/image_height look_at <-40, 150, 0> }
light_source { <-400, 300, -60> rgb 0.8 }
light_source { <-50, 300, -60> rgb <0.23, 0.23, 0.25> shadowless }
height_field {
  pot "mtmand.pot"
  pigment { rgb 1 }
  finish { ambient 0.2 diffuse 0.8 phong 0.75 phong_size 100 specular 1 roughness 0.005 }
  scale <640, 256, 480> scale <0.5625, 0.5, 1> translate <-180, 0, -240>
}
sphere { <-95, 50, 600>, 35 pigment { rgb <0.65, 0.65, 1> } }
