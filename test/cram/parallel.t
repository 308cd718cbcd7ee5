Spreading a render with GNU parallel (the README's recipe, run for real): the frames of an
animation as separate jobs (+SF/+EF pick each job's frames), and the bands of one still (+SR/+ER),
merged with povml merge; each equal to the one-process render.

  $ cat > a.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > camera { location <0, 1, -5> look_at 0 }
  > light_source { <3, 5, -5>, rgb 1 }
  > plane { y, -1 pigment { checker rgb 1, rgb 0.2 } }
  > sphere { <clock, 0, 0>, 1 pigment { rgb <1, 0.5, 0.2> } finish { reflection 0.3 } }
  > POV
  $ IMGDIFF=$PWD/../tools/imgdiff.exe
  $ mkdir one split
  $ povml a.pov +W48 +H36 +A0.3 -D +KFF12 +KI-1 +KF1 +Oone/ 2>/dev/null
  $ parallel -j 2 povml a.pov +W48 +H36 +A0.3 -D +KFF12 +KI-1 +KF1 +SF{} +EF{} +Osplit/ '2>/dev/null' ::: $(seq 1 12)
  $ ls split | tr '\n' ' '; echo
  a01.png a02.png a03.png a04.png a05.png a06.png a07.png a08.png a09.png a10.png a11.png a12.png 
  $ for f in $(ls one); do $IMGDIFF one/$f split/$f 2>/dev/null; done | sort | uniq -c
       12 differing 0/1728 (100.0000% identical) peak 0 rmse 0.0000 psnr inf

A still in four bands of whole 32-row render blocks, one job each:

  $ povml a.pov +W48 +H128 +A0.3 -D +K0.4 +Ofull.png 2>/dev/null
  $ parallel -j 2 --colsep ' ' povml a.pov +W48 +H128 +A0.3 -D +K0.4 +SR{1} +ER{2} +Oband{1}.png '2>/dev/null' ::: '1 32' '33 64' '65 96' '97 128'
  $ povml merge merged.png band1.png band33.png band65.png band97.png
  Wrote merged.png (48x128) from 4 parts
  $ $IMGDIFF full.png merged.png 2>/dev/null
  differing 0/6144 (100.0000% identical) peak 0 rmse 0.0000 psnr inf
