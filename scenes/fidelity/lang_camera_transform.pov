// povml fidelity scene: lang_camera_transform
// Rule: camera transforms (docs/povray-rules.md §1.3, §14.8): look_at first, then rotate and translate
//       applied last to location, direction, up and right; a light moved by a transform block.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  location <0, 1, -6>
  look_at <0, 1, 0>
  right x*image_width/image_height
  angle 55
  rotate <15, -25, 5>
  translate <1, 1.5, 0>
}
light_source { <0, 0, 0>, rgb 1 transform { translate <-4, 8, -5> } }
plane { y, 0 pigment { rgb <0.6, 0.7, 0.6> } }
#declare Row = 0;
#while (Row < 3)
  #for (Col, -2, 2)
    sphere { <Col * 1.2, 0.4, Row * 1.5>, 0.4 pigment { rgb <0.5 + Col / 5, 0.3 + Row / 4, 0.7> } finish { phong 0.5 } }
  #end
  #declare Row = Row + 1;
#end
