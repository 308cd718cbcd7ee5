Animations as POV-Ray's front end runs them: +KFI/+KFF give the frames (neither, or 1 to 1, is a
still), +KI/+KF the clocks, +KC a cyclic animation, +SF/+EF a subset; one image per frame, named
as POV-Ray names them (the final frame's digits), the scene read anew for each frame. The values
the scene sees are POV-Ray 3.7.0.10's (the clock in single precision; clock_delta, initial_clock
and final_clock as the front end declares them, with six significant digits).

  $ cat > a.pov <<'POV'
  > #version 3.7;
  > #debug concat("clock=", str(clock,0,17), " frame=", str(frame_number,0,0), " of ", str(initial_frame,0,0), "-", str(final_frame,0,0), " on=", str(clock_on,0,0), "\n")
  > #debug concat("delta=", str(clock_delta,0,17), " clocks=", str(initial_clock,0,17), "-", str(final_clock,0,17), "\n")
  > global_settings { assumed_gamma 1 }
  > camera { location -5*z look_at 0 }
  > light_source { <0, 5, -5>, rgb 1 }
  > sphere { <clock, 0, 0>, 1 pigment { rgb <1, 0.5, 0.2> } }
  > POV
  $ povml a.pov +W16 +H12 -D +KFI2 +KFF5 +KI0.1 +KF0.7 2>&1 | grep -E '^(Frame|clock|delta|Wrote)'
  Frame 1 of 4: frame_number 2, clock 0.100000001
  clock=0.10000000149011612 frame=2 of 2-5 on=1
  delta=0.20000000000000001 clocks=0.10000000000000001-0.69999999999999996
  Wrote a2.png (16x12)
  Frame 2 of 4: frame_number 3, clock 0.299999982
  clock=0.29999998211860657 frame=3 of 2-5 on=1
  delta=0.20000000000000001 clocks=0.10000000000000001-0.69999999999999996
  Wrote a3.png (16x12)
  Frame 3 of 4: frame_number 4, clock 0.49999997
  clock=0.49999997019767761 frame=4 of 2-5 on=1
  delta=0.20000000000000001 clocks=0.10000000000000001-0.69999999999999996
  Wrote a4.png (16x12)
  Frame 4 of 4: frame_number 5, clock 0.699999988
  clock=0.69999998807907104 frame=5 of 2-5 on=1
  delta=0.20000000000000001 clocks=0.10000000000000001-0.69999999999999996
  Wrote a5.png (16x12)

POV-Ray prints the same lines for the same switches (its clocks come from the single-precision
difference of the clocks: 1.6/7 steps, and the last frame's clock is 1.89999986, not 1.9):

  $ povml a.pov +W16 +H12 -D +KFI0 +KFF7 +KI0.3 +KF1.9 2>&1 | grep -E '^(clock|delta)=' > ml.txt
  $ IMGDIFF=$PWD/../tools/imgdiff.exe; : > empty.ini; export POVINI=$PWD/empty.ini
  $ mkdir p && cp a.pov p/ && cd p && povray +Ia.pov +W16 +H12 -D +KFI0 +KFF7 +KI0.3 +KF1.9 2>&1 | grep -E '^(clock|delta)=' > ../pov.txt; cd ..
  $ diff pov.txt ml.txt && tail -2 ml.txt
  clock=1.89999985694885254 frame=7 of 0-7 on=1
  delta=0.22857100000000000 clocks=0.29999999999999999-1.89999999999999991

The frames' names: the final frame's digits, +O's name without its extension; cyclic and subset
animations; a still when neither frame is given or both are 1.

  $ povml a.pov +W8 +H6 -D +KFF12 +Oout/x.png 2>/dev/null; ls out | tr '\n' ' '; echo
  ls: cannot access 'out': No such file or directory
  
  $ mkdir out && povml a.pov +W8 +H6 -D +KFF12 +Oout/x.png 2>/dev/null; ls out | tr '\n' ' '; echo
  x01.png x02.png x03.png x04.png x05.png x06.png x07.png x08.png x09.png x10.png x11.png x12.png 
  $ rm -r out; mkdir out && povml a.pov +W8 +H6 -D +KFF10 +KC +Oout 2>&1 | grep -c '^Frame'; ls out | tr '\n' ' '; echo
  10
  a01.png a02.png a03.png a04.png a05.png a06.png a07.png a08.png a09.png a10.png 
  $ rm -r out; mkdir out && povml a.pov +W8 +H6 -D +KFF20 +SF0.5 +EF0.75 +Oout 2>/dev/null; ls out | tr '\n' ' '; echo
  a10.png a11.png a12.png a13.png a14.png a15.png 
  $ rm -r out; mkdir out && povml a.pov +W8 +H6 -D +KFI1 +KFF1 +Oout 2>&1 | grep -E '^(clock|Wrote)'
  clock=0.00000000000000000 frame=0 of 0-0 on=0
  Wrote out/a.png (8x6)
  $ povml a.pov +W8 +H6 -D +K0.3 +Oout 2>&1 | grep -E '^clock'
  clock=0.30000001192092896 frame=0 of 0-0 on=1

An animation from an ini file, as POV-Ray's sample animations are rendered: each frame the same
image as POV-Ray's, under the same name.

  $ cat > a.ini <<'INI'
  > Input_File_Name=a.pov
  > Width=24
  > Height=18
  > Antialias=on
  > Initial_Frame=1
  > Final_Frame=4
  > Initial_Clock=-1
  > Final_Clock=1
  > Cyclic_Animation=on
  > INI
  $ mkdir ml && cp a.pov a.ini ml/ && cd ml && povml a.ini -D > /dev/null 2>&1; cd ..
  $ cp a.ini p/ && cd p && povray a.ini -D > /dev/null 2>&1; cd ..
  $ ls ml/*.png | sed 's|ml/||' | tr '\n' ' '; echo
  a1.png a2.png a3.png a4.png 
  $ for f in a1 a2 a3 a4; do $IMGDIFF p/$f.png ml/$f.png 2>/dev/null; done
  differing 0/432 (100.0000% identical) peak 0 rmse 0.0000 psnr inf
  differing 0/432 (100.0000% identical) peak 0 rmse 0.0000 psnr inf
  differing 0/432 (100.0000% identical) peak 0 rmse 0.0000 psnr inf
  differing 0/432 (100.0000% identical) peak 0 rmse 0.0000 psnr inf
