Forms of POV-Ray 3.7.0.10's language that povml once refused or misnamed, and what it says where
a scene goes beyond what it reads. Each case was checked with the installed POV-Ray (its message
is quoted); errors are located (file:line:column, the source line, a caret) and exit with 1.

What follows a '#' is read as POV-Ray reads it (Parse_Directive in tokenize.cpp): a directive name
may stand on the next line, any other word or punctuation goes on as if the '#' were not there,
and a float there is refused, as POV-Ray refuses it ("Expected 'object or directive.', float
function 'float constant' found instead"):

  $ printf '#version 3.7;\nglobal_settings { assumed_gamma 1 }\n#\n  declare R = 2;\nsphere { 0, R # pigment { rgb 1 } }\n' > hash.pov
  $ povml --dump hash.pov | grep -c sphere
  1
  $ printf '#version 3.7;\nsphere { 0, # 1 }\n' > hashnum.pov
  $ povml --dump hashnum.pov
  hashnum.pov:2:15: error: expected a directive or an object after '#' but found number 1
      2 | sphere { 0, # 1 }
        |               ^
  [1]
  $ printf '#version 3.7;\n# foreach (I, 1, 3)\n#end\n' > hashfor.pov
  $ povml --dump hashfor.pov
  hashfor.pov:2:1: error: unknown directive '#foreach'
      2 | # foreach (I, 1, 3)
        | ^
  [1]

A string may go over several lines (shapes3.inc's #warning at line 881 does); a '\' just before
the line break is refused, as POV-Ray refuses it ("Unterminated string literal."):

  $ printf '#version 3.7;\n#debug "two\nlines\\n"\n' > lines.pov
  $ povml --dump lines.pov 2>&1 >/dev/null | head -2
  two
  lines
  $ printf '#version 3.7;\n#debug "a path\\\nb"\n' > backslash.pov
  $ povml --dump backslash.pov
  backslash.pov:2:15: error: unterminated string: a '\' ends the line (POV-Ray refuses it; a backslash is written '\\')
      2 | #debug "a path\
        |               ^
  [1]

sRGB colours need assumed_gamma first ("Cannot parse sRGB colors before assumed_gamma has been
set."):

  $ printf '#version 3.7;\n#declare Red = srgb <1, 0, 0>;\nglobal_settings { assumed_gamma 1 }\n' > srgb.pov
  $ povml --dump srgb.pov
  srgb.pov:2:16: error: the sRGB colour 'srgb' needs assumed_gamma, and none has been set yet (POV-Ray refuses it too: set it in global_settings before the first sRGB colour)
      2 | #declare Red = srgb <1, 0, 0>;
        |                ^
  [1]

The noise generator is 1, 2 or 3 ("Value for noise_generator in global_settings must be 1, 2, or
3."):

  $ printf '#version 3.7;\nglobal_settings { assumed_gamma 1 noise_generator 4 }\n' > noise.pov
  $ povml --dump noise.pov
  noise.pov:2:51: error: the noise_generator must be 1, 2 or 3, not 4
      2 | global_settings { assumed_gamma 1 noise_generator 4 }
        |                                                   ^
  [1]

Cameras povml does not have yet are named where they stand, and so is focal blur (a nonzero
aperture with blur_samples; either alone changes nothing and is read):

  $ printf '#version 3.7;\ncamera { cylinder 1 location <0, 0, -5> }\n' > cylcam.pov
  $ povml --dump cylcam.pov
  cylcam.pov:2:10: error: not supported yet: 'cylinder' in a camera (the cylinder projection)
      2 | camera { cylinder 1 location <0, 0, -5> }
        |          ^
  [1]
  $ printf '#version 3.7;\ncamera {\n  location <0, 0, -5>\n  aperture 0.4\n  blur_samples 20\n  focal_point <0, 0, 0>\n}\n' > blur.pov
  $ povml --dump blur.pov
  blur.pov:4:3: error: not supported yet: focal blur (a camera with a nonzero aperture and blur_samples)
      4 |   aperture 0.4
        |   ^
  [1]
  $ printf '#version 3.7;\ncamera { blur_samples 0 }\n' > blur0.pov
  $ povml --dump blur0.pov
  blur0.pov:2:23: error: illegal number of focal blur samples: 0 (it must be at least 1)
      2 | camera { blur_samples 0 }
        |                       ^
  [1]

A mesh's hierarchy is read (it only changes speed); on other objects POV-Ray refuses it ("Keyword
'hierarchy' cannot be used with this object."):

  $ printf '#version 3.7;\nsphere { 0, 1 hierarchy off }\n' > hier.pov
  $ povml --dump hier.pov
  hier.pov:2:15: error: 'hierarchy' cannot be used with this object (only with a mesh)
      2 | sphere { 0, 1 hierarchy off }
        |               ^
  [1]

POV-Ray's reserved words povml does not read yet say so where POV-Ray would read them, in a light
source, in a union, in an expression:

  $ printf '#version 3.7;\nlight_source { <0, 5, 0>, rgb 1 area_illumination }\n' > areaillum.pov
  $ povml --dump areaillum.pov
  areaillum.pov:2:33: error: not supported yet: 'area_illumination' in a light_source
      2 | light_source { <0, 5, 0>, rgb 1 area_illumination }
        |                                 ^
  [1]
  $ printf '#version 3.7;\nunion {\n  sphere { 0, 1 }\n  composite { sphere { 0, 1 } }\n}\n' > comp.pov
  $ povml --dump comp.pov
  comp.pov:4:3: error: not supported yet: 'composite'
      4 |   composite { sphere { 0, 1 } }
        |   ^
  [1]
  $ printf '#version 3.7;\nsphere { 0, 1 translate vturbulence(2, 0.5, 6, <1, 2, 3>) }\n' > vturb.pov
  $ povml --dump vturb.pov
  // version 3.7, working gamma 1
  global_settings { max_trace_level 5 adc_bailout 0.003921568627 ambient_light rgb <1, 1, 1> }
  camera { location <0, 0, 0> direction <0, 0, 1> up <0, 1, 0> right <1.33, 0, 0> }
  background { rgb <0, 0, 0> }
  sphere { <-0.3805104063, -0.5382429719, 0.4217386875>, 1
    texture { pigment { rgb <0, 0, 0> } }
  } // vturb.pov:2:1
  // 1 objects, 0 lights
  warning: assumed_gamma not specified in this POV-Ray 3.7 or later scene; the working gamma is 1.0 (add 'assumed_gamma 1.0' to global_settings)

The others belong inside blocks povml does not read; they are reserved, as in POV-Ray, and out of
place they are the scene's error ("No matching } in 'sphere', width found instead"; "Expected
'undeclared identifier', type found instead"):

  $ printf '#version 3.7;\nsphere { 0, 1 width 2 }\n' > width.pov
  $ povml --dump width.pov
  width.pov:2:15: error: expected an object modifier or '}' closing 'sphere' but found 'width'
      2 | sphere { 0, 1 width 2 }
        |               ^
  [1]
  $ printf '#version 3.7;\n#declare type = 1;\n' > type.pov
  $ povml --dump type.pov
  type.pov:2:10: error: 'type' is a keyword and cannot be declared
      2 | #declare type = 1;
        |          ^
  [1]

Not checked here, because POV-Ray 3.7 refuses them and povml reads them (each checked with POV-Ray):
'#declare X = 1' with no ';' before the next statement (POV-Ray stops: "All #declares of float,
vector, and color require semi-colon ';' at end if the language version is set to 3.5 or higher.";
povml warns and goes on); 'camera { location 1 orthographic }' (POV-Ray wants the projection first:
"Expected 'perspective camera modifier', orthographic found instead"); 'camera { C location … }'
with C a declared camera (POV-Ray reads only transformations after the identifier: "No matching }
in 'camera', location found instead"); '#declare X = 1 # ;' (inside a float's declaration POV-Ray
keeps the '#' as a token and refuses it).
