(* Access (which files a scene may touch) and User_files (what #write writes, what #read reads). *)

(* ---- Access ---- *)

(* Removes [path] and what it holds, without following links. *)
let rec remove path =
  match (Unix.lstat path).st_kind with
  | Unix.S_DIR ->
      Array.iter (fun n -> remove (Filename.concat path n)) (Sys.readdir path);
      Unix.rmdir path
  | _ -> Sys.remove path

(* [in_sandbox f] is [f root] in a fresh directory [root] holding allowed/, allowed/sub/,
   outside/secret and links from allowed/ to outside/ and to nowhere; [root] is removed after. *)
let in_sandbox f =
  let root = Filename.temp_file "povml_access" "" in
  Sys.remove root;
  Unix.mkdir root 0o755;
  let dir p = Unix.mkdir (Filename.concat root p) 0o755 in
  dir "allowed"; dir "allowed/sub"; dir "outside";
  let touch p = close_out (open_out (Filename.concat root p)) in
  touch "allowed/a.inc"; touch "outside/secret";
  Unix.symlink (Filename.concat root "outside") (Filename.concat root "allowed/out");
  Unix.symlink (Filename.concat root "outside/new") (Filename.concat root "allowed/dangling");
  Fun.protect ~finally:(fun () -> remove root) (fun () -> f root)

let test_read () =
  in_sandbox @@ fun root ->
  let p = Filename.concat root in
  let t = Access.allow_read Access.default (p "allowed") in
  let yes msg path = Alcotest.(check bool) msg true (Access.readable t path) in
  let no msg path = Alcotest.(check bool) msg false (Access.readable t path) in
  yes "inside" (p "allowed/a.inc");
  yes "through . and .. that stay inside" (p "allowed/sub/../a.inc");
  no "outside" (p "outside/secret");
  no ".. out of the directory" (p "allowed/../outside/secret");
  no "a link out of the directory" (p "allowed/out/secret");
  no "a missing file" (p "allowed/none");
  no "/etc/passwd" "/etc/passwd";
  yes "the standard include directory" (Filename.concat Access.standard_include_dir "colors.inc");
  (* a prefix of the name is not a parent directory *)
  no "allowed2 is not under allowed" (p "allowed2");
  (* a writable directory is readable *)
  Alcotest.(check bool) "written, so read" true (Access.readable (Access.allow_write Access.default (p "outside")) (p "outside/secret"))

let test_write () =
  in_sandbox @@ fun root ->
  let p = Filename.concat root in
  let t = Access.allow_write Access.default (p "allowed") in
  let yes msg path = Alcotest.(check bool) msg true (Access.writable t path) in
  let no msg path = Alcotest.(check bool) msg false (Access.writable t path) in
  Alcotest.(check bool) "default writes nothing" false (Access.writable Access.default (p "allowed/new.txt"));
  yes "an existing file" (p "allowed/a.inc");
  yes "a new file" (p "allowed/new.txt");
  yes "in a missing directory (opening fails later)" (p "allowed/missing/new.txt");
  no "outside" (p "outside/new.txt");
  no ".. out" (p "allowed/../outside/new.txt");
  no "a missing name then .." (p "allowed/missing/../../outside/new.txt");
  no "through a link out" (p "allowed/out/new.txt");
  no "a link that leads nowhere" (p "allowed/dangling");
  Alcotest.(check bool) "reading is not writing" false (Access.writable (Access.allow_read Access.default (p "allowed")) (p "allowed/new.txt"))

let test_errors () =
  let kind f = match f () with () -> None | exception Error.Scene_error e -> Some (e.kind, e.msg) in
  (match kind (fun () -> Access.check_read Access.default Loc.none "/etc/passwd") with
  | Some (Error.Access, msg) -> Helpers.check_contains "names the switch" ~sub:"--allow-read DIR" msg
  | _ -> Alcotest.fail "an Access error");
  match kind (fun () -> Access.check_write Access.default Loc.none "out.txt") with
  | Some (Error.Access, msg) -> Helpers.check_contains "names the switch" ~sub:"--allow-write DIR" msg
  | _ -> Alcotest.fail "an Access error"

(* ---- #write and #read ---- *)

(* The strings POV-Ray 3.7.0.10 writes for these values (test/cram/file_io.t has the scene). *)
let test_text () =
  let w msg expected v = Alcotest.(check (option string)) msg expected (User_files.text v) in
  w "string" (Some "a \\ b") (Value.String "a \\ b");
  w "third" (Some "0.333333") (Value.Float (1. /. 3.));
  w "small" (Some "-2.5e-07") (Value.Float (-2.5e-7));
  w "million" (Some "1e+06") (Value.Float 1e6);
  w "negative zero" (Some "-0") (Value.Float (-0.));
  w "infinity" (Some "inf") (Value.Float infinity);
  w "vector, with a space after" (Some "<1,2.5,-3> ") (Value.Vector [| 1.; 2.5; -3. |]);
  w "2-term vector" (Some "<0.1,0.2> ") (Value.Vector [| 0.1; 0.2 |]);
  w "a colour is not written" None (Value.Colour [| 1.; 1.; 1.; 0.; 0. |])

let values text =
  let lx = Lexer.create ~file:"data.txt" text in
  let rec go acc =
    match User_files.data_value lx with
    | None, _ -> List.rev acc
    | Some v, ended -> if ended then List.rev ((v, true) :: acc) else go ((v, false) :: acc)
  in
  go []

let show (v, ended) =
  (match v with
  | Value.Float f -> Printf.sprintf "%g" f
  | Value.String s -> Printf.sprintf "%S" s
  | Value.Vector a -> "<" ^ String.concat "," (Array.to_list (Array.map (Printf.sprintf "%g") a)) ^ ">"
  | Value.Colour a -> "colour <" ^ String.concat "," (Array.to_list (Array.map (Printf.sprintf "%g") a)) ^ ">"
  | v -> Value.kind_name v)
  ^ if ended then " end" else ""

let test_data () =
  let d msg expected text = Alcotest.(check (list string)) msg expected (List.map show (values text)) in
  d "floats with signs" [ "1"; "-2.5"; "3"; "-4 end" ] "1, -2.5, +3, + + -4";
  d "the end after a comma is found by one more read" [ "1"; "2" ] "1,\n2,\n";
  d "vectors: 2 to 4 terms, 5 make a colour" [ "<1,2>"; "<1,2,3>"; "<1,2,3,4>"; "colour <1,2,3,4,5> end" ]
    "<1,2>, <1 2 3>, <1,2,3,4,>, <1,2,3,4,5>";
  d "strings with escapes" [ "\"a\\\\b\""; "\"\\\"\" end" ] "\"a\\\\b\", \"\\\"\"";
  d "comments are skipped" [ "1"; "2 end" ] "1, // one\n /* two */ 2";
  (* POV-Ray drops the token after a value that is not a comma *)
  d "without commas every other value is lost" [ "1"; "3"; "5" ] "1 2 3 4 5 6";
  d "so is an operator: no expressions" [ "1"; "2 end" ] "1+2";
  let fails msg text =
    match values text with
    | _ -> Alcotest.failf "%s: no error" msg
    | exception Error.Scene_error e -> Alcotest.(check string) (msg ^ ": in the data file") "data.txt" e.loc.file
  in
  fails "a word" "1, two";
  fails "a name in a vector" "<1, x>";
  fails "a one-term vector" "<1>";
  fails "six terms" "<1,2,3,4,5,6>"

(* Through the interpreter: no file is written without --allow-write. *)
let test_scene () =
  match Helpers.load "#fopen F \"povml_unit_never_written.txt\" write\n" with
  | _ -> Alcotest.fail "writing was allowed"
  | exception Error.Scene_error e ->
      Alcotest.(check bool) "an Access error" true (e.kind = Error.Access);
      Alcotest.(check bool) "nothing written" false (Sys.file_exists "povml_unit_never_written.txt")

let tests =
  [
    Alcotest.test_case "reading: inside the allowed directories only" `Quick test_read;
    Alcotest.test_case "writing: only under --allow-write" `Quick test_write;
    Alcotest.test_case "refusals name the switch" `Quick test_errors;
    Alcotest.test_case "#write: POV-Ray's text" `Quick test_text;
    Alcotest.test_case "#read: the values of a data file" `Quick test_data;
    Alcotest.test_case "a scene writes nothing by default" `Quick test_scene;
  ]
