(* Whole_file: a file written whole or not at all; and Png_text.whole, which Output checks the
   encoder's bytes with. *)

let with_dir f =
  let dir = Filename.temp_file "povml-whole" "" in
  Sys.remove dir;
  Unix.mkdir dir 0o700;
  Fun.protect ~finally:(fun () -> Array.iter (fun e -> Sys.remove (Filename.concat dir e)) (Sys.readdir dir); Unix.rmdir dir) (fun () -> f dir)

let read path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in ic) (fun () -> really_input_string ic (in_channel_length ic))

let entries dir = List.sort compare (Array.to_list (Sys.readdir dir))
let ok = function Ok () -> () | Error m -> Alcotest.failf "unexpected error: %s" m

let test_replace () =
  with_dir (fun dir ->
      let path = Filename.concat dir "a" in
      ok (Whole_file.write path "first");
      ok (Whole_file.write path "second, longer");
      Alcotest.(check string) "the new bytes" "second, longer" (read path);
      Alcotest.(check int) "ordinary permissions" 0o644 ((Unix.stat path).st_perm land 0o777);
      Alcotest.(check (list string)) "no temporary file" [ "a" ] (entries dir))

let test_link () =
  with_dir (fun dir ->
      let file = Filename.concat dir "file" and link = Filename.concat dir "link" in
      ok (Whole_file.write file "old, and longer");
      Unix.symlink "file" link;
      ok (Whole_file.write link "new");
      Alcotest.(check bool) "the link stays" true ((Unix.lstat link).st_kind = S_LNK);
      Alcotest.(check string) "its file has the new bytes, nothing after them" "new" (read file))

let test_device () =
  (match Whole_file.write "/dev/full" "bytes" with
  | Ok () -> Alcotest.fail "wrote to /dev/full"
  | Error m -> Alcotest.(check string) "the reason" "No space left on device" m);
  Alcotest.(check bool) "/dev/full stays a device" true ((Unix.stat "/dev/full").st_kind = S_CHR);
  ok (Whole_file.write "/dev/null" "bytes")

let test_directory () =
  with_dir (fun dir ->
      match Whole_file.write dir "bytes" with
      | Ok () -> Alcotest.fail "wrote onto a directory"
      | Error m -> Alcotest.(check string) "the reason" "it is a directory; nothing was written" m)

(* A file that cannot be created (its directory is missing): the reason names the directory. *)
let test_missing_dir () =
  with_dir (fun dir ->
      let missing = Filename.concat dir "missing" in
      match Whole_file.write (Filename.concat missing "a") "bytes" with
      | Ok () -> Alcotest.fail "wrote into a missing directory"
      | Error m -> Alcotest.(check string) "the reason" (missing ^ ": No such file or directory; nothing was written") m)

let png () =
  let e = { Encode.width = 3; height = 2; pixels = Bytes.init 18 (fun i -> Char.chr (i * 13)) } in
  with_dir (fun dir ->
      let path = Filename.concat dir "a.png" in
      ok (Output.write Output.Png path e);
      read path)

let test_png_whole () =
  let s = png () in
  Alcotest.(check bool) "povml's PNG is whole" true (Png_text.whole s);
  Alcotest.(check bool) "cut short, it is not" false (Png_text.whole (String.sub s 0 (String.length s - 1)));
  Alcotest.(check bool) "with a byte after it, it is not" false (Png_text.whole (s ^ "\000"));
  let bad = Bytes.of_string s in
  Bytes.set bad 40 (Char.chr (Char.code (Bytes.get bad 40) lxor 1));
  Alcotest.(check bool) "with a changed byte (its chunk's CRC fails), it is not" false (Png_text.whole (Bytes.to_string bad));
  Alcotest.(check bool) "nothing is not" false (Png_text.whole "")

let test_png_add () =
  let s = Png_text.add (png ()) ~key:"k" ~value:"v" in
  Alcotest.(check bool) "still whole" true (Png_text.whole s);
  with_dir (fun dir ->
      let path = Filename.concat dir "t.png" in
      ok (Whole_file.write path s);
      Alcotest.(check (option string)) "found again" (Some "v") (Png_text.find path ~key:"k"))

let tests =
  [
    Alcotest.test_case "a file replaced" `Quick test_replace;
    Alcotest.test_case "a symbolic link's file replaced" `Quick test_link;
    Alcotest.test_case "a device written into, its errors told" `Quick test_device;
    Alcotest.test_case "a directory refused" `Quick test_directory;
    Alcotest.test_case "a missing directory" `Quick test_missing_dir;
    Alcotest.test_case "Png_text.whole" `Quick test_png_whole;
    Alcotest.test_case "Png_text.add" `Quick test_png_add;
  ]
