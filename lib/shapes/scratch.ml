(* The per-worker scratch of the intersection routines, and the list of a CSG's member hits. *)

type slab = { mutable t_near : float; mutable t_far : float }
type growable = { mutable room : float array }

(* The heap grows by the block asked for plus space_overhead percent of it (expand_heap in the
   runtime's memory.c): that margin is set to its least for the allocation. *)
let big_floats n =
  let gc = Gc.get () in
  if gc.space_overhead <= 200 then Array.make n 0.
  else begin
    Gc.set { gc with space_overhead = 1 };
    Fun.protect ~finally:(fun () -> Gc.set gc) (fun () -> Array.make n 0.)
  end

type blob_room = {
  mutable bounds : float array;
  mutable marks : int array;
  mutable fcoeffs : float array;
  mutable queue : int array;
  mutable found : float array;
  acc : float array;
}

type iso_search = {
  mutable px : float;
  mutable py : float;
  mutable pz : float;
  mutable dx : float;
  mutable dy : float;
  mutable dz : float;
  mutable inv3 : float;
  mutable maxg : float;
  mutable fmax : float;
  mutable tl : float;
  mutable vlength : float;
  mutable bx : float;
  mutable by : float;
  mutable bz : float;
  mutable ex : float;
  mutable ey : float;
  mutable ez : float;
  mutable frame : float array;
}

type iso_own = { frame : float array; mutable grad_used : float }

type iso_room = { mutable cached : bool; mutable owner : int; at : iso_search; mutable own : iso_own option array }

let iso_room () =
  {
    cached = false;
    owner = -1;
    own = [||];
    at =
      { px = 0.; py = 0.; pz = 0.; dx = 0.; dy = 0.; dz = 0.; inv3 = 1.; maxg = 0.; fmax = 0.; tl = 0.; vlength = 0.; bx = 0.; by = 0.; bz = 0.;
        ex = 0.; ey = 0.; ez = 0.; frame = [||] };
  }

type f32s = (float, Bigarray.float32_elt, Bigarray.c_layout) Bigarray.Array1.t
type vertex_normals = { mutable fields : (f32s * f32s) list }

type t = {
  stats : Stats.t;
  lim : Limits.t;
  robust : bool;
  mesh_stack : float array;
  mesh_depth : float array;
  mutable part : int;
  mutable leaf : int;
  slab : slab;
  mutable side_near : int;
  mutable side_far : int;
  crossings : float array;
  glyph_crossings : growable;
  hits : growable;
  coeffs : float array;
  roots : float array;
  depths : float array;
  quartic : Polysolv.work;
  blob : blob_room;
  curve : growable;
  sextic : Polysolv.work;
  bcyl : growable;
  sextic_coeffs : float array;
  sextic_roots : float array;
  lathe_quadratic : float array;
  lathe_quadratic_roots : float array;
  fractal_stack : growable;
  crossing : Crossing.t;
  mutable reported : bool;
  reports : growable;
  mutable report_count : int;
  poly_room : float array;
  iso : iso_room;
  iso_hits : float array;
  mutable shadow_ray : bool;
  vertex_normals : vertex_normals;
}

let hit_width = 7

(* A cylinder or cone has at most 4 crossings listed (two on the side, the two ends), a disc one,
   a torus 4 depths, a quadric 2, a polygon 1. *)
let max_crossings = 8

let create ~robust stats =
  {
    stats;
    lim = (if robust then Limits.robust else Limits.pov);
    robust;
    mesh_stack = Array.make 512 0.;
    mesh_depth = [| 0. |];
    part = -1;
    leaf = -1;
    slab = { t_near = 0.; t_far = 0. };
    side_near = 0;
    side_far = 0;
    crossings = Array.make max_crossings 0.;
    glyph_crossings = { room = Array.make 64 0. };
    hits = { room = Array.make (64 * hit_width) 0. };
    coeffs = Array.make 5 0.;
    roots = Array.make 4 0.;
    depths = Array.make 4 0.;
    quartic = Polysolv.create ();
    blob = { bounds = [||]; marks = [||]; fcoeffs = [||]; queue = [||]; found = Array.make 16 0.; acc = Array.make 8 0. };
    curve = { room = Array.make 64 0. };
    sextic = Polysolv.create ();
    bcyl = { room = Array.make 64 0. };
    sextic_coeffs = Array.make 7 0.;
    sextic_roots = Array.make 6 0.;
    lathe_quadratic = Array.make 3 0.;
    lathe_quadratic_roots = Array.make 2 0.;
    fractal_stack = { room = Array.make 84 0. };
    crossing = Crossing.create ();
    reported = false;
    reports = { room = Array.make (16 * Crossing.width) 0. };
    report_count = 0;
    poly_room = Array.make 512 0.;
    iso = iso_room ();
    iso_hits = Array.make 32 0.;
    shadow_ray = false;
    vertex_normals = { fields = [] };
  }

let renew w stats = { w with stats; part = -1; leaf = -1; side_near = 0; side_far = 0; reported = false; report_count = 0; shadow_ray = false }

(* a room whose [cached] is false answers every search as a new one would: the rest of [at] is
   written by a search before it is read, or read only where [cached] holds *)
let forget_iso_cache w = w.iso.cached <- false

let forget_isosurfaces w =
  forget_iso_cache w;
  w.iso.owner <- -1;
  w.iso.own <- [||]

let push_hit w n t part id px py pz =
  let width = hit_width in
  if (n + 1) * width > Array.length w.hits.room then begin
    let bigger = Array.make (2 * Array.length w.hits.room) 0. in
    Array.blit w.hits.room 0 bigger 0 (n * width);
    w.hits.room <- bigger
  end;
  let h = w.hits.room and j = n * width in
  h.(j) <- t;
  h.(j + 1) <- Float.of_int part;
  h.(j + 2) <- Float.of_int id;
  h.(j + 3) <- px;
  h.(j + 4) <- py;
  h.(j + 5) <- pz;
  h.(j + 6) <- -1.;
  n + 1

let push_reported w n t id =
  let c = w.crossing and width = Crossing.width in
  let r = w.report_count in
  if (r + 1) * width > Array.length w.reports.room then begin
    let bigger = Array.make (2 * Array.length w.reports.room) 0. in
    Array.blit w.reports.room 0 bigger 0 (r * width);
    w.reports.room <- bigger
  end;
  Crossing.store c w.reports.room (r * width);
  w.report_count <- r + 1;
  let m = push_hit w n t (-1) id (Crossing.point_x c) (Crossing.point_y c) (Crossing.point_z c) in
  w.hits.room.((n * hit_width) + 6) <- Float.of_int r;
  m

let hit_report w j =
  let r = int_of_float w.hits.room.((j * hit_width) + 6) in
  if r >= 0 then Crossing.load w.reports.room (r * Crossing.width) w.crossing;
  r >= 0

let push_ray w n lo t part id (o : Vec.t) (d : Vec.t) =
  if t >= lo then push_hit w n t part id (o.x +. (t *. d.x)) (o.y +. (t *. d.y)) (o.z +. (t *. d.z)) else n

let nearest_pair w (h : float array) n lo =
  let best = ref infinity and part = ref 0 in
  for i = n - 1 downto 0 do
    let t = h.(2 * i) in
    if t < !best && t >= lo then begin
      best := t;
      part := int_of_float h.((2 * i) + 1)
    end
  done;
  if !best < infinity then w.part <- !part;
  !best

let nearest_crossing w n lo = nearest_pair w w.crossings n lo

let nearest_depth w n lo =
  let best = ref infinity in
  for i = n - 1 downto 0 do
    let t = w.crossings.(i) in
    if t < !best && t >= lo then best := t
  done;
  !best
