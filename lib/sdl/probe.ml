(* The parse-time questions a scene may ask of an object: trace(), inside(), min_extent() and
   max_extent() (POV-Ray's express.cpp: Parse_Trace, Parse_Inside, the extent functions). The
   object is compiled as the tracer would see it, once per object asked in a row. *)

open Reader

(* The object whole, as a top-level object of its own: a union is not dissolved and keeps its
   bounding objects (it is not linked into the scene). Reading it must not add its lights to the
   scene or count it as an object. *)
let scene_object st (o : V.obj) : Scene.obj =
  let lights = st.lights and count = st.object_count in
  let o =
    match o.shape with
    | Prim _ when o.inverted ->
        (* an inverted primitive alone: the intersection of itself, as it enters the scene *)
        let m = V.Member_obj { o with texture = None; interior_texture = None; interior = None } in
        { o with shape = Csg { kind = Intersection; members = [ m ]; split = false; box = None }; inverted = false }
    | Prim _ | Csg _ -> o
  in
  let _, interior = Csg_build.resolved st o in
  let obj = Csg_build.kept_obj st ~texture:None ~cut_parent:false ~interior o in
  st.lights <- lights;
  st.object_count <- count;
  obj

let camera = { Scene.location = Vec.zero; direction = Vec.make 0. 0. 1.; up = Vec.make 0. 1. 0.; right = Vec.make 1. 0. 0.; projection = Perspective }

(* The compiled object, from the last one compiled when it is the same object *)
let compiled st (o : V.obj) =
  match st.probed with
  | Some (o', sc) when o' == o -> sc
  | Some _ | None ->
      let scene =
        {
          Scene.camera;
          objects = [ scene_object st o ];
          lights = [];
          background = Colour.black;
          sky = None;
          ambient_light = st.ambient_light;
          max_trace_level = st.max_trace_level;
          adc_bailout = st.adc_bailout;
          version = st.version;
          noise_generator = st.noise_generator;
          irid_wavelength = st.irid_wavelength;
          gamma = Gamma_off;
          shift = 0.;
        }
      in
      let sc = Compile.scene scene in
      (* its isosurfaces are numbered anew: what the parser's thread kept for the last object's
         goes, as the object it was kept for does *)
      if Lazy.is_val st.probe_work then Scratch.forget_isosurfaces (Lazy.force st.probe_work);
      st.probed <- Some (o, sc);
      sc

let top (sc : Compiled.t) = sc.objects.(0)

let trace st (o : V.obj) (origin : Vec.t) (dir : Vec.t) =
  let sc = compiled st o in
  let ob = top sc in
  let d = Vec.normalize dir in
  let w = Scratch.renew (Lazy.force st.probe_work) (Stats.create ()) in
  (* Find_Intersection: the object's box (which spheres, boxes, planes and triangles never
     test), then every hit at MIN_ISECT_DEPTH or beyond, popped from the stack: the first of the
     nearest wins *)
  let boxed = Array.length ob.pbox > 0 && not (Shape.box_test_free ob.shape) in
  if boxed && Pov_box.entry ob.pbox origin d = infinity then None
  else begin
    let n = Shape.all_hits w (Compile.member ob) origin d Precision.min_isect_depth 0 in
    let h = w.hits.room and width = Scratch.hit_width in
    let best = ref (-1) in
    for j = n - 1 downto 0 do
      if !best < 0 || h.(j * width) < h.(!best * width) then best := j
    done;
    if !best < 0 then None
    else
      let b = !best * width in
      let leaf = sc.objects.(int_of_float h.(b + 2)) and part = int_of_float h.(b + 1) in
      (* a julia fractal reports the point its march found and the normal there, a bicubic
         patch its normal, a parametric surface its (u, v) *)
      let c = if Scratch.hit_report w !best then w.crossing else Crossing.none in
      let p = Shape.hit_point w leaf c origin h.(b) d in
      let nrm = Shape.hit_normal w leaf part c p in
      Some (p, if leaf.inverted then Vec.neg nrm else nrm)
  end

let inside st (o : V.obj) p =
  let sc = compiled st o in
  Shape.inside (Array.make 512 0.) (top sc).shape p

let extent st (o : V.obj) =
  let b = (top (compiled st o)).pbox in
  (* an unbounded object has POV-Ray's huge box *)
  let b = if Array.length b = 0 then [| -1e10; -1e10; -1e10; 2e10; 2e10; 2e10 |] else b in
  let f32 = Precision.f32 in
  (Vec.make b.(0) b.(1) b.(2), Vec.make (f32 (b.(0) +. b.(3))) (f32 (b.(1) +. b.(4))) (f32 (b.(2) +. b.(5))))

(* The calls: trace(OBJECT, A, B [, N]), inside(OBJECT, P), min_extent(OBJECT), max_extent(OBJECT).
   trace's optional last argument is a vector identifier that receives the normal at the hit
   (<0,0,0> on a miss); max_extent of an image map pigment is the image's size. *)
let parse st name ~vector:parse_vector =
  advance st;
  expect st LParen (Printf.sprintf "'(' after '%s'" name);
  let oloc = peek_loc st in
  let target =
    match peek st with
    | Ident s -> (
        match cur_value st s with
        | Some (V.Object o) -> advance st; `Object o
        | Some (V.Pigment p) -> advance st; `Pigment p
        | Some (V.Unsupported u) -> unsupported_use oloc s u.what u.at
        | _ -> `None)
    | _ -> `None
  in
  let of_vec (v : Vec.t) = V.Vector [| v.x; v.y; v.z |] in
  let result =
    match (name, target) with
    | "max_extent", `Pigment (Scene.Pattern { pattern = Bitmap b; _ }) ->
        V.Vector [| float_of_int b.image.width; float_of_int b.image.height; 0. |]
    | "max_extent", `Pigment _ -> Error.raise_at oloc "The parameter to max_extent must be an image map pigment identifier"
    | ("min_extent" | "max_extent"), `Object o ->
        let lo, hi = extent st o in
        of_vec (if name = "min_extent" then lo else hi)
    | ("min_extent" | "max_extent"), (`None | `Pigment _) -> Error.raise_at oloc "'%s' needs an object identifier" name
    | "inside", `Object o ->
        if Csg_build.patch o then Error.raise_at oloc "Solid object identifier expected.";
        expect st Comma "',' after the object of 'inside'";
        let p = parse_vector st in
        V.Float (if inside st o p then 1. else 0.)
    | _, `Object o ->
        expect st Comma "',' after the object of 'trace'";
        let origin = parse_vector st in
        expect st Comma "',' after the start of 'trace'";
        let dir = parse_vector st in
        let hit = trace st o origin dir in
        if accept st Comma then begin
          let nloc = peek_loc st in
          let nrm = match hit with Some (_, n) -> n | None -> Vec.zero in
          match peek st with
          | Ident s -> (
              match (cur_value st s, st.cur_elem) with
              | Some (V.Vector _), Some (a, i) -> advance st; a.cells.(i) <- Some (of_vec nrm)
              | Some (V.Vector _), None -> (
                  advance st;
                  match lookup_cell st s with Some cell -> cell := of_vec nrm | None -> ())
              | _ -> Error.raise_at nloc "trace's fourth argument must be a declared vector identifier (it receives the normal)")
          | _ -> Error.raise_at nloc "trace's fourth argument must be a declared vector identifier (it receives the normal)"
        end;
        of_vec (match hit with Some (p, _) -> p | None -> Vec.zero)
    | _, (`None | `Pigment _) -> Error.raise_at oloc "Object identifier expected."
  in
  expect st RParen (Printf.sprintf "')' closing the arguments of '%s'" name);
  result
