Image files made to break the decoders (test/tools/hostile_image.ml writes them, the large ones
here at test time): each is refused with a located error, exit status 1 (3 for one above a
limit), within 20 seconds and 1 GiB of address space, and no image is written. The decoders are
a library of their own built without -unsafe (lib/image_files/dune), so an index they forgot to check would
raise rather than read outside an array.

  $ mk() { ../tools/hostile_image.exe "$@"; }
  $ run() {
  >   kind=$1; file=$2; shift 2
  >   printf '#version 3.7;\nglobal_settings { assumed_gamma 1 }\ncamera { location <0, 0, -3> look_at 0 }\nplane { z, 0 pigment { image_map { %s "%s" } } }\n' "$kind" "$file" > s.pov
  >   rm -f s.png
  >   (ulimit -v 1048576 && exec timeout 20 povml s.pov +W16 +H12 -D "$@") 2>err.txt >/dev/null
  >   status=$?
  >   sed '/^------/,$d' err.txt
  >   if [ -f s.png ]; then echo "[exit $status, image written]"; else echo "[exit $status, no image]"; fi
  > }

GIF: POV-Ray's Decode (gifdecod.cpp) takes LZW code sizes 2 to 9 only; larger ones made povml
segfault or say "Char.chr".

  $ mk gif-code-size-13 a.gif && run gif a.gif
  s.pov:4:36: error: cannot read the image file "a.gif": the GIF's LZW code size 13 is above 9
      4 | plane { z, 0 pigment { image_map { gif "a.gif" } } }
        |                                    ^
  [exit 1, no image]
  $ mk gif-code-size-1 a.gif && run gif a.gif
  s.pov:4:36: error: cannot read the image file "a.gif": the GIF's LZW code size 1 is below 2
      4 | plane { z, 0 pigment { image_map { gif "a.gif" } } }
        |                                    ^
  [exit 1, no image]

A 2-entry colour table and indices up to 255 (POV-Ray reads outside its colour map; povml's
render segfaulted):

  $ mk gif-index-beyond-table a.gif && run gif a.gif
  s.pov:4:36: error: cannot read the image file "a.gif": the GIF's pixel at column 3, row 1 has colour index 2, beyond its 2-entry colour table
      4 | plane { z, 0 pigment { image_map { gif "a.gif" } } }
        |                                    ^
  [exit 1, no image]

A 0×0 GIF (POV-Ray aborts; povml said "index out of bounds" while rendering), more pixels than the
image holds (POV-Ray: "Extra data in GIF file"), and a size above the pixel cap:

  $ mk gif-0x0 a.gif && run gif a.gif
  s.pov:4:36: error: cannot read the image file "a.gif": the GIF's image is 0×0 pixels: it has none
      4 | plane { z, 0 pigment { image_map { gif "a.gif" } } }
        |                                    ^
  [exit 1, no image]
  $ mk gif-extra-pixels a.gif && run gif a.gif
  s.pov:4:36: error: cannot read the image file "a.gif": the GIF's image data holds more than its 4 pixels
      4 | plane { z, 0 pigment { image_map { gif "a.gif" } } }
        |                                    ^
  [exit 1, no image]
  $ mk gif-65535x65535 a.gif && run gif a.gif
  s.pov:4:36: error: cannot read the image file "a.gif": the GIF's size 65535×65535 is above povml's limit of 67,108,864 pixels (raise it with --max-pixels N)
      4 | plane { z, 0 pigment { image_map { gif "a.gif" } } }
        |                                    ^
  [exit 3, no image]

PPM: a width × height × 3 that overflows segfaulted a render; sizes are checked against the cap and
the file's length before anything is allocated.

  $ mk ppm-overflow a.ppm && run ppm a.ppm
  s.pov:4:36: error: cannot read the image file "a.ppm": the PPM's size 2305843009213693952×4 is above povml's limit of 67,108,864 pixels (raise it with --max-pixels N)
      4 | plane { z, 0 pigment { image_map { ppm "a.ppm" } } }
        |                                    ^
  [exit 3, no image]
  $ mk ppm-huge a.ppm && run ppm a.ppm --max-pixels 100000000000
  s.pov:4:36: error: cannot read the image file "a.ppm": the PPM's 100000×100000 pixels need 228,881 MiB once decoded, more than povml's memory limit of 512 MiB (raise it with --max-memory MIB)
      4 | plane { z, 0 pigment { image_map { ppm "a.ppm" } } }
        |                                    ^
  [exit 3, no image]
  $ mk ppm-short a.ppm && run ppm a.ppm
  s.pov:4:36: error: cannot read the image file "a.ppm": the PPM's size 64×64 needs at least 12,288 bytes of pixel data, but the file holds 64
      4 | plane { z, 0 pigment { image_map { ppm "a.ppm" } } }
        |                                    ^
  [exit 1, no image]
  $ mk ppm-ascii-short a.ppm && run ppm a.ppm
  s.pov:4:36: error: cannot read the image file "a.ppm": the PPM's size 4000×4000 needs at least 96,000,000 bytes of pixel data, but the file holds 7
      4 | plane { z, 0 pigment { image_map { ppm "a.ppm" } } }
        |                                    ^
  [exit 1, no image]
  $ mk pgm-negative a.pgm && run pgm a.pgm
  s.pov:4:36: error: cannot read the image file "a.pgm": invalid width or height
      4 | plane { z, 0 pigment { image_map { pgm "a.pgm" } } }
        |                                    ^
  [exit 1, no image]

An ASCII number longer than any int was "int_of_string"; POV-Ray's atoi stores its low bits:

  $ mk ppm-ascii-long-number a.ppm && run ppm a.ppm
  [exit 0, image written]

PNG: a 1×1 image whose data inflates to more than a gigabyte took 1.67 GB; decompression now stops
at the size the header promises (libpng ignores the rest).

  $ mk png-bomb a.png && run png a.png
  [exit 0, image written]

libpng refuses a critical chunk whose CRC does not match and an IHDR it does not allow
(png_check_IHDR); povml accepted both.

  $ mk png-bad-crc a.png && run png a.png
  s.pov:4:36: error: cannot read the image file "a.png": the PNG's IDAT chunk is damaged (its CRC does not match its data)
      4 | plane { z, 0 pigment { image_map { png "a.png" } } }
        |                                    ^
  [exit 1, no image]
  $ mk png-bit-depth-3 a.png && run png a.png
  s.pov:4:36: error: cannot read the image file "a.png": the PNG's bit depth 3 is not 1, 2, 4, 8 or 16
      4 | plane { z, 0 pigment { image_map { png "a.png" } } }
        |                                    ^
  [exit 1, no image]
  $ mk png-rgb-depth-4 a.png && run png a.png
  s.pov:4:36: error: cannot read the image file "a.png": the PNG's bit depth 4 is not allowed with its colour type 2
      4 | plane { z, 0 pigment { image_map { png "a.png" } } }
        |                                    ^
  [exit 1, no image]
  $ mk png-2000000x1 a.png && run png a.png
  s.pov:4:36: error: cannot read the image file "a.png": the PNG's size 2000000×1 is above libpng's limit of 1,000,000 pixels a side
      4 | plane { z, 0 pigment { image_map { png "a.png" } } }
        |                                    ^
  [exit 1, no image]
  $ mk png-100000x100000 a.png && run png a.png
  s.pov:4:36: error: cannot read the image file "a.png": the PNG's size 100000×100000 is above povml's limit of 67,108,864 pixels (raise it with --max-pixels N)
      4 | plane { z, 0 pigment { image_map { png "a.png" } } }
        |                                    ^
  [exit 3, no image]

A size within the caps but far more than its compressed data can hold (deflate inflates at most
1,032 times): refused before the samples are allocated, as libpng runs out of data.

  $ mk png-8000x8000-tiny a.png && run png a.png --max-memory 100000
  s.pov:4:36: error: cannot read the image file "a.png": the PNG's 111 bytes of compressed data cannot hold its 8000×8000 pixels (192,008,000 bytes once inflated; deflate inflates at most 1,032 times)
      4 | plane { z, 0 pigment { image_map { png "a.png" } } }
        |                                    ^
  [exit 1, no image]
  $ mk png-no-plte a.png && run png a.png
  s.pov:4:36: error: cannot read the image file "a.png": the PNG has colour type 3 (a palette) but no PLTE chunk
      4 | plane { z, 0 pigment { image_map { png "a.png" } } }
        |                                    ^
  [exit 1, no image]

Targa: sizes against the cap and the file's length.

  $ mk tga-65535x65535 a.tga && run tga a.tga
  s.pov:4:36: error: cannot read the image file "a.tga": the Targa's size 65535×65535 is above povml's limit of 67,108,864 pixels (raise it with --max-pixels N)
      4 | plane { z, 0 pigment { image_map { tga "a.tga" } } }
        |                                    ^
  [exit 3, no image]
  $ mk tga-rle-short a.tga && run tga a.tga
  s.pov:4:36: error: cannot read the image file "a.tga": the Targa's size 2048×2048 needs at least 32,768 run-length packets, but the file holds 4 bytes of pixel data
      4 | plane { z, 0 pigment { image_map { tga "a.tga" } } }
        |                                    ^
  [exit 1, no image]

JPEG, through povml's own libjpeg binding (lib/image_files/jpeg_stubs.c) rather than camlimages': libjpeg's
own lines ("Premature end of JPEG file") no longer come before the located error; a file that
ends early is refused, as POV-Ray refuses it; a damaged Huffman table, which made camlimages'
binding segfault, is libjpeg's message, as in POV-Ray; a declared size above the cap is refused
before libjpeg allocates it.

  $ mk jpeg-truncated a.jpg && run jpeg a.jpg
  s.pov:4:36: error: cannot read the image file "a.jpg": Premature end of JPEG file
      4 | plane { z, 0 pigment { image_map { jpeg "a.jpg" } } }
        |                                    ^
  [exit 1, no image]
  $ mk jpeg-bogus-huffman a.jpg && run jpeg a.jpg
  s.pov:4:36: error: cannot read the image file "a.jpg": Bogus Huffman table definition
      4 | plane { z, 0 pigment { image_map { jpeg "a.jpg" } } }
        |                                    ^
  [exit 1, no image]

hostile_segv.jpg is one of the 240 in 1,500 mutated JPEGs of the decoder fuzz run
(test/fuzz/test_fuzz_images.ml) that segfaulted povml through camlimages; POV-Ray says the same:

  $ cp hostile_segv.jpg b.jpg && run jpeg b.jpg
  s.pov:4:36: error: cannot read the image file "b.jpg": Quantization table 0x01 was not defined
      4 | plane { z, 0 pigment { image_map { jpeg "b.jpg" } } }
        |                                    ^
  [exit 1, no image]
  $ mk jpeg-65500x65500 a.jpg && run jpeg a.jpg
  s.pov:4:36: error: cannot read the image file "a.jpg": the JPEG's size 65500×65500 is above povml's limit of 67,108,864 pixels (raise it with --max-pixels N)
      4 | plane { z, 0 pigment { image_map { jpeg "a.jpg" } } }
        |                                    ^
  [exit 3, no image]

TrueType: a font whose one character is made of 12⁸ glyphs (composite glyphs naming composite glyphs,
8 deep) ran out of stack with "the scene nests too deeply" (POV-Ray: std::bad_alloc); now a
bounded number of glyphs and points per character:

  $ mk ttf-nested-composites n.ttf
  $ printf '#version 3.7;\nglobal_settings { assumed_gamma 1 }\ncamera { location <0, 0, -3> look_at 0 }\ntext { ttf "n.ttf" "A" 0.1, 0 }\n' > t.pov
  $ (ulimit -v 1048576 && exec timeout 20 povml t.pov +W16 +H12 -D) 2>err.txt >/dev/null; echo "[exit $?]"; sed '/^------/,$d' err.txt
  [exit 1]
  t.pov:4:12: error: the font file "n.ttf" cannot be read: a composite glyph is made of more than 10000 glyphs
      4 | text { ttf "n.ttf" "A" 0.1, 0 }
        |            ^

A smooth height field from a 1-pixel image: POV-Ray stops the parse with "Failed to find any
normals at."; povml said so unlocated, as an internal error (exit 70).

  $ printf 'P5\n1 1\n255\n\200' > one.pgm
  $ printf '#version 3.7;\nglobal_settings { assumed_gamma 1 }\ncamera { location <0, 2, -2> look_at 0 }\nheight_field { pgm "one.pgm" smooth }\n' > hf.pov
  $ (ulimit -v 1048576 && exec timeout 20 povml hf.pov +W16 +H12 -D) 2>err.txt >/dev/null; echo "[exit $?]"; sed '/^------/,$d' err.txt
  [exit 1]
  hf.pov:4:16: error: Failed to find any normals at. (a smooth height_field needs an image at least 2×2 pixels; "one.pgm" is 1×1)
      4 | height_field { pgm "one.pgm" smooth }
        |                ^

povml merge: a part of huge declared size or a decompression bomb was exit 70; now a clear error
in bounded memory, or the part read as far as its header promises.

  $ mk png-100000x100000 part.png
  $ (ulimit -v 1048576 && exec timeout 20 povml merge out.png part.png); echo "[exit $?]"
  povml merge: error: part.png: cannot read it: the PNG's 100000×100000 pixels need 457,763 MiB once decoded, more than povml's memory limit of 512 MiB
  [exit 1]
  $ mk png-bomb part.png
  $ (ulimit -v 1048576 && exec timeout 20 povml merge out.png part.png); echo "[exit $?]"
  povml merge: error: part.png: it does not say which part of the image it renders (povml records that in every PNG it writes; POV-Ray's do not)
  [exit 1]
  $ ls out.png
  ls: cannot access 'out.png': No such file or directory
  [2]
