(* Shared helpers for the unit tests. *)

let opts = Interp.default_options ~width:160 ~height:120

(* [load text] interprets [text] as the file "t.pov". *)
let load text = Interp.load_string opts ~file:"t.pov" text
let scene text = fst (load text)
let warnings text = snd (load text)

let float_eq ?(eps = 1e-9) msg expected actual = Alcotest.(check (float eps)) msg expected actual

let vec_eq ?(eps = 1e-9) msg (e : Vec.t) (a : Vec.t) =
  float_eq ~eps (msg ^ " (x)") e.x a.x;
  float_eq ~eps (msg ^ " (y)") e.y a.y;
  float_eq ~eps (msg ^ " (z)") e.z a.z

let rgb_eq ?(eps = 1e-9) msg (e : Rgb.t) (a : Rgb.t) =
  float_eq ~eps (msg ^ " (r)") e.r a.r;
  float_eq ~eps (msg ^ " (g)") e.g a.g;
  float_eq ~eps (msg ^ " (b)") e.b a.b

let colour_eq ?(eps = 1e-9) msg (e : Colour.t) (a : Colour.t) =
  float_eq ~eps (msg ^ " (red)") e.red a.red;
  float_eq ~eps (msg ^ " (green)") e.green a.green;
  float_eq ~eps (msg ^ " (blue)") e.blue a.blue;
  float_eq ~eps (msg ^ " (filter)") e.filter a.filter;
  float_eq ~eps (msg ^ " (transmit)") e.transmit a.transmit

let colour5 r g b f t = { Colour.red = r; green = g; blue = b; filter = f; transmit = t }

let contains ~sub s =
  let ls = String.length s and lsub = String.length sub in
  let rec go i = i + lsub <= ls && (String.sub s i lsub = sub || go (i + 1)) in
  go 0

let check_contains msg ~sub s =
  if not (contains ~sub s) then Alcotest.failf "%s: expected %S to contain %S" msg s sub

(* [expect_error f ~line ~col ~sub] checks that [f ()] raises [Error.Scene_error] at line:col with a
   message containing [sub]. *)
let expect_error ?(file = "t.pov") msg f ~line ~col ~sub =
  match f () with
  | _ -> Alcotest.failf "%s: expected a Scene_error, got a result" msg
  | exception Error.Scene_error e ->
      Alcotest.(check string) (msg ^ " (file)") file e.loc.file;
      Alcotest.(check int) (msg ^ " (line)") line e.loc.line;
      Alcotest.(check int) (msg ^ " (col)") col e.loc.col;
      check_contains msg ~sub e.msg

let expect_scene_error msg text ~line ~col ~sub = expect_error msg (fun () -> load text) ~line ~col ~sub

(* The only object of a scene. *)
let the_object (s : Scene.t) =
  match s.objects with [ o ] -> o | l -> Alcotest.failf "expected one object, got %d" (List.length l)

let sphere_of (o : Scene.obj) =
  match o.shape with Sphere { centre; radius; _ } -> (centre, radius) | _ -> Alcotest.fail "expected a sphere"

let plane_of (o : Scene.obj) =
  match o.shape with Plane { normal; offset; _ } -> (normal, offset) | _ -> Alcotest.fail "expected a plane"

(* the top layer of an object's texture *)
let layer_of (o : Scene.obj) = match o.texture with Layers (l :: _) -> l | _ -> Alcotest.fail "a patterned texture"

(* the compiled surface of a plain texture *)
let surf_of (o : Compiled.obj) = match o.tex with Plain s -> s | _ -> Alcotest.fail "not a plain texture"

let pigment_of (o : Scene.obj) = match (layer_of o).pigment with Solid c | Solid_placed { colour = c; _ } -> c | Pattern _ -> Alcotest.fail "a pattern pigment"

(* Tracing one ray through a scene given as text, compiled with the bounding threshold of Debian's
   povray.ini (3), with which POV-Ray checked these rules (reference/povray.ini) *)
let compile ?(bounding_threshold = 3) text = Compile.scene ~bounding_threshold (scene text)

let trace_ray ?interiors (c : Compiled.t) origin dir =
  let ctx = Trace.make_ctx c (Stats.create ()) in
  let interiors = match interiors with Some l -> l | None -> c.start_interiors in
  Trace.trace ctx ~level:0 ~weight:1. ~interiors ~continued:false origin (Vec.normalize dir)

let trace_text ?interiors text origin dir = trace_ray ?interiors (compile text) origin dir

(* Traced colours are rounded to single precision: compare with 1e-6. *)
let result_eq ?(eps = 1e-6) msg (r, g, b) (res : Trace.result) =
  float_eq ~eps (msg ^ " (r)") r res.r;
  float_eq ~eps (msg ^ " (g)") g res.g;
  float_eq ~eps (msg ^ " (b)") b res.b

let v = Vec.make

(* Render options for a w×h image: no antialiasing, one worker, 32-pixel blocks, no progress line. *)
let render_opts w h = { (Render.defaults w h) with jitter = 0. }
