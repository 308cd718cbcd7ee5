(* Render statistics: the counters one worker keeps, and their sum over workers. *)

(* every counter's tests, at its key, and hits, just after: two ints a counter, no allocation to
   count, and the sum over workers is one array's *)
type counts = int array

type t = {
  mutable camera_rays : int;
  mutable reflected_rays : int;
  mutable refracted_rays : int;
  mutable shadow_rays : int;
  mutable max_level : int;
  mutable samples : int;
  counts : counts;
  mutable iso_found : float array;
}

(* a counter's place in [counts]: even, its hits at the next *)
type key = int

(* the keys are constants below [2 * counters], so that [counts] needs no bounds check *)
let[@inline] test s k = let c = s.counts in Array.unsafe_set c k (Array.unsafe_get c k + 1)
let[@inline] hit s k = let c = s.counts in Array.unsafe_set c (k + 1) (Array.unsafe_get c (k + 1) + 1)
let[@inline] untest s k = let c = s.counts in Array.unsafe_set c k (Array.unsafe_get c k - 1)
let[@inline] unhit s k = let c = s.counts in Array.unsafe_set c (k + 1) (Array.unsafe_get c (k + 1) - 1)
let tests s k = s.counts.(k)
let hits s k = s.counts.(k + 1)

(* the counters: the solvers', then those of the table's lines; a new one takes the next even
   number, and goes in [solvers] or [table] *)
let roots = 0
let isosurface_roots = 2
let parametric_cut = 4
let blob = 6
let blob_element = 8
let blob_bound = 10
let bicubic = 12
let box = 14
let cone = 16
let disc = 18
let csg_intersection = 20
let csg_merge = 22
let csg_union = 24
let hfield = 26
let hfield_box = 28
let hfield_triangle = 30
let hfield_block = 32
let hfield_cell = 34
let isosurface = 36
let isosurface_container = 38
let isosurface_cache = 40
let lathe = 42
let lathe_bound = 44
let fractal = 46
let plane = 48
let polygon = 50
let prism = 52
let prism_bound = 54
let parametric = 56
let parametric_bound = 58
let quadric = 60
let poly = 62
let triangle = 64
let mesh = 66
let ovus = 68
let sphere = 70
let sphere_sweep = 72
let superellipsoid = 74
let sor = 76
let sor_bound = 78
let torus = 80
let torus_bound = 82
let glyph = 84
let bounding_object = 86

(* the lines of POV-Ray's "Ray->Shape Intersection" table, in its order (renderfrontend.cpp):
   each a counter *)
let table =
  [
    ("Blob", blob);
    ("Blob Component", blob_element);
    ("Blob Bound", blob_bound);
    ("Bicubic Patch", bicubic);
    ("Box", box);
    ("Cone/Cylinder", cone);
    ("Disc", disc);
    ("CSG Intersection", csg_intersection);
    ("CSG Merge", csg_merge);
    ("CSG Union", csg_union);
    ("Height Field", hfield);
    ("Height Field Box", hfield_box);
    ("Height Field Triangle", hfield_triangle);
    ("Height Field Block", hfield_block);
    ("Height Field Cell", hfield_cell);
    ("Isosurface", isosurface);
    ("Isosurface Container", isosurface_container);
    ("Isosurface Cache", isosurface_cache);
    ("Lathe", lathe);
    ("Lathe Bound", lathe_bound);
    ("Fractal", fractal);
    ("Plane", plane);
    ("Polygon", polygon);
    ("Prism", prism);
    ("Prism Bound", prism_bound);
    ("Parametric", parametric);
    ("Parametric Bound", parametric_bound);
    ("Quadric", quadric);
    ("Quartic/Poly", poly);
    ("Triangle", triangle);
    ("Mesh", mesh);
    ("Ovus", ovus);
    ("Sphere", sphere);
    ("Sphere Sweep", sphere_sweep);
    ("Superellipsoid", superellipsoid);
    ("Surface of Revolution", sor);
    ("Surface of Rev. Bound", sor_bound);
    ("Torus", torus);
    ("Torus Bound", torus_bound);
    ("True Type Font", glyph);
    ("Bounding Object", bounding_object);
  ]

(* the counters that are no line of the table *)
let solvers = [ roots; isosurface_roots; parametric_cut ]

let counters = List.length solvers + List.length table

(* every counter once, its tests and hits within [counts]: the keys are 0, 2, … in some order *)
let () = assert (List.sort compare (solvers @ List.map snd table) = List.init counters (fun i -> 2 * i))

let iso_width = 5

let create () =
  { camera_rays = 0; reflected_rays = 0; refracted_rays = 0; shadow_rays = 0; max_level = 0; samples = 0; counts = Array.make (2 * counters) 0; iso_found = [||] }

(* the room of isosurface [key], the array grown (with zeros) when it is too short *)
let iso_slot s key =
  let need = (key + 1) * iso_width in
  if Array.length s.iso_found < need then begin
    let a = Array.make (max need (2 * Array.length s.iso_found)) 0. in
    Array.blit s.iso_found 0 a 0 (Array.length s.iso_found);
    s.iso_found <- a
  end;
  key * iso_width

(* the per-isosurface values of two workers: largest gradients and variation, summed counts *)
let merge_found a b =
  let n = max (Array.length a) (Array.length b) in
  let get x i = if i < Array.length x then x.(i) else 0. in
  Array.init n (fun i ->
      let x = get a i and y = get b i in
      match i mod iso_width with 2 | 3 -> x +. y | _ -> if x < y then y else x)

let merge a b =
  {
    camera_rays = a.camera_rays + b.camera_rays;
    reflected_rays = a.reflected_rays + b.reflected_rays;
    refracted_rays = a.refracted_rays + b.refracted_rays;
    shadow_rays = a.shadow_rays + b.shadow_rays;
    max_level = max a.max_level b.max_level;
    samples = a.samples + b.samples;
    counts = Array.map2 ( + ) a.counts b.counts;
    iso_found = merge_found a.iso_found b.iso_found;
  }

type row = { name : string; tests : int; hits : int }

let rows s = List.map (fun (name, k) -> { name; tests = tests s k; hits = hits s k }) table
