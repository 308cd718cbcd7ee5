povml merge OUT PART… joins partial renders (+SR/+ER/+SC/+EC; each PNG povml writes records the
area it rendered and its render block size) into the image one render writes: identical,
antialiasing at band edges included, when the parts are made of whole render blocks (32 pixels,
+BS): antialiasing compares a pixel with its neighbours within its block only.

  $ cat > s.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > camera { location <0, 1, -5> look_at 0 }
  > light_source { <3, 5, -5>, rgb 1 }
  > plane { y, -1 pigment { checker rgb 1, rgb 0.2 } }
  > sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } finish { reflection 0.3 } }
  > POV
  $ IMGDIFF=$PWD/../tools/imgdiff.exe
  $ povml s.pov +W64 +H80 +A0.3 -D +Ofull.png 2>/dev/null
  $ for b in "1 32" "33 64" "65 80"; do set -- $b; povml s.pov +W64 +H80 +A0.3 -D +SR$1 +ER$2 +Oband$1.png 2>/dev/null; done
  $ povml merge merged.png band1.png band33.png band65.png
  Wrote merged.png (64x80) from 3 parts
  $ $IMGDIFF full.png merged.png 2>/dev/null
  differing 0/5120 (100.0000% identical) peak 0 rmse 0.0000 psnr inf

Tiles too (the area may be given as fractions), in any order:

  $ povml s.pov +W64 +H80 +A0.3 -D +SC1 +EC0.5 +Oleft.png 2>/dev/null
  $ povml s.pov +W64 +H80 +A0.3 -D +SC0.5 +EC64 +SR1 +ER0.4 +Otopright.png 2>/dev/null
  $ povml s.pov +W64 +H80 +A0.3 -D +SC0.5 +SR0.4 +Obottomright.png 2>/dev/null
  $ povml merge tiles.png topright.png left.png bottomright.png && $IMGDIFF full.png tiles.png 2>/dev/null
  Wrote tiles.png (64x80) from 3 parts
  differing 0/5120 (100.0000% identical) peak 0 rmse 0.0000 psnr inf

Parts that end off a block's edge still merge, with a warning: antialiased pixels along those
edges may differ from one render's.

  $ povml s.pov +W64 +H80 +A0.3 -D +ER20 +Otop20.png 2>/dev/null
  $ povml s.pov +W64 +H80 +A0.3 -D +SR21 +Orest.png 2>/dev/null
  $ povml merge odd.png top20.png rest.png
  povml merge: warning: top20.png: its area (columns 1 to 64, rows 1 to 20) does not begin and end on the edges of 32-pixel render blocks: antialiased pixels along its edges may differ from one render's
  povml merge: warning: rest.png: its area (columns 1 to 64, rows 21 to 80) does not begin and end on the edges of 32-pixel render blocks: antialiased pixels along its edges may differ from one render's
  Wrote odd.png (64x80) from 2 parts
  $ $IMGDIFF full.png odd.png 2>/dev/null
  differing 4/5120 (99.9219% identical) peak 28 rmse 0.5160 psnr 53.88

Parts that do not fit together: a clear error, status 1, no image.

  $ povml merge out.png band1.png band65.png; echo "exit $?"
  povml merge: error: no part renders column 1, row 33: the parts leave a gap
  exit 1
  $ povml merge out.png band1.png band33.png full.png; echo "exit $?"
  povml merge: error: band1.png and full.png overlap: both render column 1, row 1
  exit 1
  $ povml s.pov +W32 +H24 -D +Osmall.png 2>/dev/null
  $ povml merge out.png band1.png small.png; echo "exit $?"
  povml merge: error: small.png is 32x24 but band1.png is 64x80: the parts of one image have its size
  exit 1
  $ printf 'not a png' > junk.png
  $ povml merge out.png junk.png; echo "exit $?"
  povml merge: error: junk.png: cannot read it: not a PNG file
  exit 1
  $ ls out.png
  ls: cannot access 'out.png': No such file or directory
  [2]
