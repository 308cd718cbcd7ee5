A text object is text { ttf "font.ttf" "string", thickness, offset } (§15.9). The font file is
searched like an include file and read through the access policy. A missing or unusable font file,
a missing string and an internal font give a located error and exit status 1:

  $ printf 'text { ttf "nofont.ttf" "Hello", 0.1, 0 }\n' > nofont.pov
  $ povml nofont.pov +W10 +H10 -D 2>&1 | head -3
  nofont.pov:1:12: error: cannot find the font file "nofont.ttf" (searched ., /usr/share/povray-3.7/include)
      1 | text { ttf "nofont.ttf" "Hello", 0.1, 0 }
        |            ^
  $ printf 'not a font at all, just some text that is long enough\n' > bad.ttf
  $ printf 'text { ttf "bad.ttf" "Hello", 0.1, 0 }\n' > badfont.pov
  $ povml badfont.pov +W10 +H10 -D
  badfont.pov:1:12: error: the font file "bad.ttf" is not a usable TrueType font: the file ends inside a table (cannot read the TrueType font)
      1 | text { ttf "bad.ttf" "Hello", 0.1, 0 }
        |            ^
  [1]
  $ printf 'text { ttf "cyrvetic.ttf", 0.1, 0 }\n' > nostring.pov
  $ povml nostring.pov +W10 +H10 -D
  nostring.pov:1:28: error: text needs the string to render (a string) here, not a float
      1 | text { ttf "cyrvetic.ttf", 0.1, 0 }
        |                            ^
  [1]
  $ printf 'text { ttf "cyrvetic.ttf" }\n' > nothing.pov
  $ povml nothing.pov +W10 +H10 -D
  nothing.pov:1:27: error: text needs the string to render here
      1 | text { ttf "cyrvetic.ttf" }
        |                           ^
  [1]
  $ printf 'text { internal 1 "Hello", 0.1, 0 }\n' > internal.pov
  $ povml internal.pov +W10 +H10 -D
  internal.pov:1:8: error: internal fonts are not supported yet: name a TrueType font file with ttf "file.ttf"
      1 | text { internal 1 "Hello", 0.1, 0 }
        |        ^
  [1]
  $ printf 'text { ttf "cyrvetic.ttf" "Hi", 0.1 }\n' > nooffset.pov
  $ povml nooffset.pov +W10 +H10 -D
  nooffset.pov:1:37: error: expected a numeric expression but found '}'
      1 | text { ttf "cyrvetic.ttf" "Hi", 0.1 }
        |                                     ^
  [1]

A font outside the allowed directories is refused:

  $ mkdir -p elsewhere && cp bad.ttf elsewhere/x.ttf
  $ printf 'text { ttf "%s/elsewhere/x.ttf" "Hi", 0.1, 0 }\n' "$PWD" > outside.pov
  $ mkdir -p scene && mv outside.pov scene/ && cd scene
  $ povml outside.pov +W10 +H10 -D 2>&1 | sed "s|$(dirname "$PWD")|DIR|" | head -1
  outside.pov:1:12: error: reading "DIR/elsewhere/x.ttf" is not allowed: it is outside the scene's directory, the working directory and the library paths (allow it with --allow-read DIR)
  $ cd ..

The dump shows each letter as a glyph, placed by its transform (its place in the string, the
tiny turn POV-Ray gives every text, then the modifiers); the statistics count the letters' tests:

  $ printf '#version 3.7;\nglobal_settings { assumed_gamma 1 }\ntext { ttf "cyrvetic.ttf" "I", 0.25, 0 translate y }\n' > dump.pov
  $ povml --dump dump.pov 2>&1 | grep -A1 glyph
  glyph { // 1 contours, 4 segments, box <79, 0> … <178, 728> of 1000 units per em, depth 0.25
    matrix <0.9999999997, 1.745329252e-05, -1.745329252e-05, -1.74529879e-05, 0.9999999997, 1.745329252e-05, 1.745359713e-05, -1.74529879e-05, 0.9999999997, -0.07899999998, 0.9999986212, 1.378810109e-06>
  $ printf '#version 3.7;\nlight_source { <0, 5, -5>, 1 }\nsphere { <0,0,3>, 1 pigment { rgb 1 } }\ntext { ttf "cyrvetic.ttf" "I", 0.25, 0 translate y pigment { rgb 1 } }\n' > stats.pov
  $ povml stats.pov +W20 +H10 -D 2>&1 | grep "True Type"
  True Type Font                      43               5       11.63

The string is read by the charset: with ascii (the default) a non-ASCII character becomes spaces,
with a warning; utf8 decodes it; sys cannot be converted, as in POV-Ray on Unix:

  $ printf '#version 3.7;\nglobal_settings { assumed_gamma 1 }\ntext { ttf "cyrvetic.ttf" "caf\303\251", 0.1, 0 }\n' > ascii.pov
  $ povml ascii.pov +W10 +H10 -D 2>&1 | head -3
  ascii.pov:3:27: warning: a non-ASCII character of the text string has been replaced by a space (the charset is ascii; write global_settings { charset utf8 })
      3 | text { ttf "cyrvetic.ttf" "café", 0.1, 0 }
        |                           ^
  $ printf '#version 3.7;\nglobal_settings { assumed_gamma 1 charset utf8 }\ntext { ttf "cyrvetic.ttf" "caf\303\251", 0.1, 0 }\n' > utf8.pov
  $ povml --dump utf8.pov 2>&1 | grep -c glyph
  4
  $ printf '#version 3.7;\nglobal_settings { assumed_gamma 1 charset sys }\ntext { ttf "cyrvetic.ttf" "caf\303\251", 0.1, 0 }\n' > sys.pov
  $ povml sys.pov +W10 +H10 -D
  sys.pov:3:27: error: charset sys: the string cannot be converted from the system's text format to Unicode (use charset utf8)
      3 | text { ttf "cyrvetic.ttf" "café", 0.1, 0 }
        |                           ^
  [1]

A font name without an extension is also tried with ".ttf":

  $ printf '#version 3.7;\nglobal_settings { assumed_gamma 1 }\ntext { ttf "cyrvetic" "I", 0.25, 0 }\n' > noext.pov
  $ povml --dump noext.pov 2>&1 | grep -c glyph
  1
