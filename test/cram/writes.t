Every write povml makes is checked to its last byte, flushed and synced before it is renamed onto
the output path. When it fails (a full disk, a device that refuses, a file size limit) povml says
why with the system's words and exits with status 5, and the file that was at the path is kept
as it was. test/full_disk fills a real (tmpfs) file system; here /dev/full (every write to it
fails with "No space left on device") and a file size limit (ulimit -f, with SIGXFSZ ignored, so
that a write past it fails with "File too large") stand in for a full disk.

  $ cat > s.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > camera { location <0, 0, -3> look_at 0 }
  > light_source { <3, 5, -5>, rgb 1 }
  > sphere { 0, 1 pigment { granite scale 0.05 } }
  > POV
  $ limited () { (trap '' XFSZ; ulimit -f 4; "$@"); }
  $ no_temporary_file () { ls -A | grep -e '\.part' -e '^\.povml' || echo "no temporary file"; }

A device that refuses the bytes: nothing is said to be written.

  $ povml s.pov +W8 +H6 -D +O/dev/full 2>err; echo "exit $?"; grep -e error -e Wrote err
  exit 5
  /dev/full: error: cannot write the image: No space left on device
  $ povml s.pov +W8 +H6 -D +FP +O/dev/full 2>err; echo "exit $?"; grep -e error -e Wrote err
  exit 5
  /dev/full: error: cannot write the image: No space left on device
  $ test -c /dev/full && echo "/dev/full is still a device"
  /dev/full is still a device

An image larger than the disk can take, PNG or PPM (+FP): the old image stays, byte for byte,
and no temporary file is left beside it. One render process (+WT1), as the render processes'
own files would meet the limit first.

  $ povml s.pov +W64 +H48 -D +Oold.png 2>/dev/null && cp old.png old.png.before
  $ povml s.pov +W64 +H48 -D +FP +Oold.ppm 2>/dev/null && cp old.ppm old.ppm.before
  $ limited povml s.pov +W160 +H120 +WT1 -D +Oold.png 2>err; echo "exit $?"; grep -e error -e Wrote err
  exit 5
  old.png: error: cannot write the image: File too large; the old file is kept
  $ cmp old.png old.png.before && echo "old.png unchanged"
  old.png unchanged
  $ limited povml s.pov +W160 +H120 +WT1 -D +FP +Oold.ppm 2>err; echo "exit $?"; grep -e error -e Wrote err
  exit 5
  old.ppm: error: cannot write the image: File too large; the old file is kept
  $ cmp old.ppm old.ppm.before && echo "old.ppm unchanged"
  old.ppm unchanged
  $ no_temporary_file
  no temporary file

The render processes hand their results back through files in the temporary directory (TMPDIR):
when those cannot be written, no image is written either.

  $ TMPDIR=$PWD/missing povml s.pov +W64 +H48 +WT2 -D +Oold.png 2>err; echo "exit $?"; grep -e cannot -e Wrote err | sed "s|$PWD|PWD|"
  exit 5
  povml: cannot write the render processes' results in PWD/missing: No such file or directory; no image was written
  $ cmp old.png old.png.before && echo "old.png unchanged"
  old.png unchanged
  $ limited povml s.pov +W160 +H120 +WT2 -D +Oold.png 2>err; echo "exit $?"; grep -e cannot -e Wrote err | sed "s|$TMPDIR|TMPDIR|"
  exit 5
  povml: cannot write the render processes' results in TMPDIR: File too large; no image was written
  $ cmp old.png old.png.before && echo "old.png unchanged"
  old.png unchanged

Where there was no file, none is left:

  $ limited povml s.pov +W160 +H120 +WT1 -D +Onew.png 2>err; echo "exit $?"; grep -e error -e Wrote err
  exit 5
  new.png: error: cannot write the image: File too large; nothing was written
  $ ls new.png
  ls: cannot access 'new.png': No such file or directory
  [2]
  $ no_temporary_file
  no temporary file

The same image within the limit is written, as is a symbolic link's file, the link kept:

  $ limited povml s.pov +W16 +H12 +WT1 -D +Oold.png 2>err; echo "exit $?"; grep -e error -e Wrote err
  exit 0
  Wrote old.png (16x12)
  $ ln -s old.ppm link.ppm
  $ limited povml s.pov +W160 +H120 +WT1 -D +FP +Olink.ppm 2>err; echo "exit $?"; grep -e error err
  exit 5
  link.ppm: error: cannot write the image: File too large; the old file is kept
  $ test -L link.ppm && cmp old.ppm old.ppm.before && echo "link and file unchanged"
  link and file unchanged
  $ povml s.pov +W160 +H120 -D +FP +Olink.ppm 2>/dev/null; test -L link.ppm && head -c 11 old.ppm | od -An -c
     P   6  \n   1   6   0       1   2   0  \n

Animation frames: the first frame that cannot be written stops the animation with status 5, its
old file kept.

  $ cp old.png.before frame1.png
  $ limited povml s.pov +W160 +H120 +WT1 -D +KFI1 +KFF2 +Oframe.png 2>err; echo "exit $?"; grep -e error -e Wrote err
  exit 5
  frame1.png: error: cannot write the image: File too large; the old file is kept
  $ cmp frame1.png old.png.before && echo "frame1.png unchanged"; ls frame2.png
  frame1.png unchanged
  ls: cannot access 'frame2.png': No such file or directory
  [2]

povml merge writes the same way:

  $ povml s.pov +W160 +H120 -D +ER64 +Otop.png 2>/dev/null
  $ povml s.pov +W160 +H120 -D +SR65 +Obottom.png 2>/dev/null
  $ povml merge /dev/full top.png bottom.png; echo "exit $?"
  povml merge: error: cannot write /dev/full: No space left on device
  exit 5
  $ cp old.png.before merged.png
  $ limited povml merge merged.png top.png bottom.png; echo "exit $?"; cmp merged.png old.png.before && echo "merged.png unchanged"
  povml merge: error: cannot write merged.png: File too large; the old file is kept
  exit 5
  merged.png unchanged
  $ mkdir dir
  $ povml merge dir top.png bottom.png; echo "exit $?"
  povml merge: error: cannot write dir: it is a directory; nothing was written
  exit 5
  $ povml merge out.png top.png dir; echo "exit $?"
  povml merge: error: dir: cannot read it: it is a directory, not a PNG file
  exit 1
  $ no_temporary_file
  no temporary file

A scene's own file (#fopen … write, #write, #fclose) that cannot be written is an error of the
scene at the #write (status 1), with the system's reason:

  $ cat > w.pov <<'POV'
  > #version 3.7;
  > #fopen F "/dev/full" write
  > #write (F, "a line\n")
  > #fclose F
  > POV
  $ povml w.pov --allow-write /dev -D -F
  w.pov:3:1: error: cannot write "/dev/full": No space left on device
      3 | #write (F, "a line\n")
        | ^
  [1]
  $ cat > big.pov <<'POV'
  > #version 3.7;
  > #fopen F "big.bin" write
  > #for (I, 1, 2000)
  >   #write (F, uint8 I I I)
  > #end
  > #fclose F
  > POV
  $ limited povml big.pov --allow-write . -D -F
  big.pov:4:3: error: cannot write "big.bin": File too large
      4 |   #write (F, uint8 I I I)
        |   ^
  [1]
