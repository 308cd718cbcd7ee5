(* The path from a scene file to an encoded image: read, compile, render, encode, timing each. *)

type result = {
  image : Encode.t;
  raw : Image.t;
  stats : Stats.t;
  warnings : Error.t list;
  scene : Scene.t;
  includes : (string * float) list;
  parse_seconds : float;
  build_seconds : float;
  render_seconds : float;
}

(* DispatchShutdownMessages: POV-Ray's word on the max_gradient of each top-level isosurface that
   is not a copy, at its function *)
type watched = { isosurfaces : Isosurface.t list; first_parametric : Parametric.t option }

(* what the warnings after the render look at, kept so that the scene's objects need not be *)
let watched (scene : Scene.t) =
  {
    isosurfaces = List.filter_map (fun (o : Scene.obj) -> match o.shape with Isosurface s when not s.copy -> Some s | _ -> None) scene.objects;
    first_parametric = List.find_map (fun (o : Scene.obj) -> match o.shape with Parametric p -> Some p | _ -> None) scene.objects;
  }

let shutdown_warnings (w : watched) (stats : Stats.t) =
  let iso = List.filter_map (fun (s : Isosurface.t) -> Option.map (Error.warning s.fn.floc) (Isosurface.warning s stats)) w.isosurfaces in
  (* povml's own limit on a parametric surface's search, said once, at the first one *)
  let cut = Stats.tests stats Stats.parametric_cut in
  let cut =
    if cut = 0 then []
    else
      match w.first_parametric with
      | None -> []
      | Some p ->
          [ Error.warning p.fx.floc
              (Printf.sprintf
                 "povml stopped %d searches of parametric surfaces after %d pieces each (its limit: their u and v ranges are far wider than max_gradient lets the search tell apart); those rays may miss the surface"
                 cut Parametric.max_pieces) ]
  in
  iso @ cut

(* The robust mode traces the scene moved near the origin, by the camera's position rounded to a
   grid of 16 times the camera's size (a power of 2): hit points are then as precise however far
   the scene lies from the origin, and so are the error bounds, which grow with the coordinates
   (Robust). A scene around the origin is not moved; a scene moved far away comes back by an exact
   amount, so each coordinate keeps the rounding it got on the way out and no more. *)
let recentred (scene : Scene.t) =
  let c = scene.camera in
  let size = Float.max (Vec.length c.direction) (Float.max (Vec.length c.right) (Vec.length c.up)) in
  if not (size > 0. && Float.is_finite size) then scene
  else
    let grid = Float.ldexp 1. (snd (Float.frexp size) + 4) in
    let snap x = if Float.is_finite x then Float.round (x /. grid) *. grid else 0. in
    let t = Vec.make (snap c.location.x) (snap c.location.y) (snap c.location.z) in
    if t.x = 0. && t.y = 0. && t.z = 0. then scene else Place.scene ~scale:1. ~translate:(Vec.neg t) scene

(* 512 MB *)
let large_heap = 64 * 1024 * 1024

let run ?interp ?move ?bounding_threshold (opts : Render.options) path =
  let t0 = Unix.gettimeofday () in
  let iopts = match interp with Some i -> i | None -> Interp.default_options ~width:opts.width ~height:opts.height in
  let includes = ref [] in
  let included p ~depth dt = iopts.included p ~depth dt; if depth = 1 then includes := (p, dt) :: !includes in
  let scene, warnings = Interp.load_file { iopts with width = opts.width; height = opts.height; included } path in
  (* taken now: a pattern's field left to be read where it is used would keep the pair, and with
     it the whole scene, alive until then *)
  let warnings = Sys.opaque_identity warnings in
  let scene = match move with None -> scene | Some (scale, translate) -> Place.scene ~scale ~translate scene in
  let scene = if opts.robust then recentred scene else scene in
  let t1 = Unix.gettimeofday () in
  (* the compiled scene is all the render needs: the scene's objects are let go as they are
     compiled (nothing here holds them meanwhile), and a large heap is compacted before worker
     processes are forked from it, so that a scene of a million objects renders in the memory it
     needs once, not twice *)
  let watched = watched scene in
  let rest = { scene with objects = [] } in
  let compiled = Compile.scene ?bounding_threshold scene in
  let scene = rest in
  if (Gc.quick_stat ()).heap_words > large_heap then begin
    (* a compaction keeps [space_overhead] percent of the live data free (compact.c): kept small
       here, the heap shrinks to about what the render reads *)
    let gc = Gc.get () in
    Gc.set { gc with space_overhead = 20 };
    Gc.compact ();
    Gc.set gc
  end;
  let t2 = Unix.gettimeofday () in
  let img, stats = Render.render opts compiled scene.gamma in
  let image = Encode.image scene.gamma img in
  let t3 = Unix.gettimeofday () in
  let warnings = warnings @ shutdown_warnings watched stats in
  { image; raw = img; stats; warnings; scene; includes = List.rev !includes; parse_seconds = t1 -. t0; build_seconds = t2 -. t1; render_seconds = t3 -. t2 }
