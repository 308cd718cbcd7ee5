(* The render loop: antialiasing methods 1 (§9.3) and 2 (§9.4) in blocks, each sample a camera
   ray ({!Camera}) traced, and the split of blocks over processes. Every block is computed independently from the scene alone,
   so the image is the same for any number of workers. *)

open Compiled

type area = { left : int; right : int; top : int; bottom : int }

type aa_method = Non_adaptive | Adaptive

type options = {
  width : int;
  height : int;
  antialias : float option;
  aa_method : aa_method;
  aa_depth : int;
  jitter : float;
  aa_gamma : float;
  area : area;
  block_size : int;
  workers : int;
  progress : bool;
  robust : bool;
}

let full_area w h = { left = 0; right = w - 1; top = 0; bottom = h - 1 }

let defaults w h =
  {
    width = w;
    height = h;
    antialias = None;
    aa_method = Non_adaptive;
    aa_depth = 3;
    jitter = 1.;
    aa_gamma = 2.5;
    area = full_area w h;
    block_size = 32;
    workers = 1;
    progress = false;
    robust = false;
  }

(* A camera ray traced: a new ray from trace level 0 with weight 1 (§1.4) *)
let traced ctx interiors o d = Trace.trace ctx ~level:0 ~weight:1. ~interiors ~continued:false o d

(* One sample: the camera ray through the image position (x, y), traced *)
let sample ctx cam x y =
  ctx.Context.stats.camera_rays <- ctx.stats.camera_rays + 1;
  Camera.ray cam ctx x y traced

(* §9.1: colours are compared after x ↦ max(x,0)^(1/aa_gamma), in the working space. *)
let aa_distance enc (a : Trace.result) (b : Trace.result) =
  Float.abs (enc a.r -. enc b.r) +. Float.abs (enc a.g -. enc b.g) +. Float.abs (enc a.b -. enc b.b) +. Float.abs (a.tr -. b.tr)

(* §9.3: supersample pixel (x, y) whose first sample is [c]. *)
let supersample ctx opts cam (c : Trace.result) x y : Trace.result =
  let depth = opts.aa_depth in
  let step = 1. /. float_of_int depth in
  let js = opts.jitter /. float_of_int depth in
  let r0 = 0.5 -. (step /. 2.) in
  let fx = float_of_int x and fy = float_of_int y in
  let sr = ref c.r and sg = ref c.g and sb = ref c.b and st = ref c.tr in
  let yy = ref (-.r0) in
  while !yy <= r0 +. 1e-10 do
    let xx = ref (-.r0) in
    while !xx <= r0 +. 1e-10 do
      let px = fx +. !xx and py = fy +. !yy in
      let s =
        if js = 0. then sample ctx cam px py
        else sample ctx cam (px +. (Jitter.jx px py *. js)) (py +. (Jitter.jy px py *. js))
      in
      ctx.stats.samples <- ctx.stats.samples + 1;
      sr := Precision.f32 (!sr +. s.r);
      sg := Precision.f32 (!sg +. s.g);
      sb := Precision.f32 (!sb +. s.b);
      st := Precision.f32 (!st +. s.tr);
      xx := !xx +. step
    done;
    yy := !yy +. step
  done;
  let n = float_of_int ((depth * depth) + 1) in
  { r = Precision.f32 (!sr /. n); g = Precision.f32 (!sg /. n); b = Precision.f32 (!sb /. n); tr = Precision.f32 (!st /. n) }

type block = { bx0 : int; by0 : int; bx1 : int; by1 : int }

(* No antialiasing: one sample at each pixel centre. *)
let plain_block ctx cam (b : block) store =
  for y = b.by0 to b.by1 do
    for x = b.bx0 to b.bx1 do
      store x y (sample ctx cam (float_of_int x) (float_of_int y))
    done
  done

(* §9.3, method 1. *)
let non_adaptive_block ctx opts cam enc thr (b : block) store =
  let bw = b.bx1 - b.bx0 + 1 and bh = b.by1 - b.by0 + 1 in
  (* A (bw+1)×(bh+1) grid whose row 0 and column 0 are the re-traced row above and column left
     of the block; those are never supersampled (§9.3). *)
  let gw = bw + 1 in
  let px = Array.make (gw * (bh + 1)) Trace.black in
  let done_ = Array.make (gw * (bh + 1)) false in
  let at x y = ((y - b.by0 + 1) * gw) + (x - b.bx0 + 1) in
  let tr x y = sample ctx cam (float_of_int x) (float_of_int y) in
  for x = b.bx0 to b.bx1 do
    px.(at x (b.by0 - 1)) <- tr x (b.by0 - 1);
    done_.(at x (b.by0 - 1)) <- true
  done;
  for y = b.by0 to b.by1 do
    px.(at (b.bx0 - 1) y) <- tr (b.bx0 - 1) y;
    done_.(at (b.bx0 - 1) y) <- true;
    for x = b.bx0 to b.bx1 do
      let c = tr x y in
      px.(at x y) <- c;
      let ld = aa_distance enc px.(at (x - 1) y) c >= thr in
      let td = aa_distance enc px.(at x (y - 1)) c >= thr in
      let sl = (not done_.(at (x - 1) y)) && ld in
      let st = (not done_.(at x (y - 1))) && td in
      if sl then begin
        px.(at (x - 1) y) <- supersample ctx opts cam px.(at (x - 1) y) (x - 1) y;
        done_.(at (x - 1) y) <- true
      end;
      if st then begin
        px.(at x (y - 1)) <- supersample ctx opts cam px.(at x (y - 1)) x (y - 1);
        done_.(at x (y - 1)) <- true
      end;
      if ld || td then begin
        px.(at x y) <- supersample ctx opts cam c x y;
        done_.(at x y) <- true
      end
    done
  done;
  for y = b.by0 to b.by1 do
    for x = b.bx0 to b.bx1 do
      store x y px.(at x y)
    done
  done

(* The mean of four colours, summed in this order in single precision as POV-Ray does. *)
let mean4 (a : Trace.result) (b : Trace.result) (c : Trace.result) (d : Trace.result) : Trace.result =
  let m a b c d = Precision.f32 (Precision.f32 (Precision.f32 (Precision.f32 (a +. b) +. c) +. d) /. 4.) in
  { r = m a.r b.r c.r d.r; g = m a.g b.g c.g d.g; b = m a.b b.b c.b d.b; tr = m a.tr b.tr c.tr d.tr }

(* §9.4, method 2. The block's pixel corners are traced first, without jitter; then each pixel is
   subdivided recursively on an (S+1)×(S+1) lattice of sub-sample positions, S = 2^depth, of which
   only the four corners are shared with neighbouring pixels. As in POV-Ray a pixel is split at most
   depth−1 times (so every other lattice line stays unused, and depth 1 is the mean of the corners),
   and the jitter is scaled by 1/(S+1). Corners are re-traced by each block at the same positions,
   so unlike method 1 the image does not depend on the block size. *)
let adaptive_block ctx opts cam enc thr (b : block) store =
  let bw = b.bx1 - b.bx0 + 1 and bh = b.by1 - b.by0 + 1 in
  (* corners.(i + j·cw) is the top-left corner of pixel (bx0 + i, by0 + j) *)
  let cw = bw + 1 in
  let corners = Array.make (cw * (bh + 1)) Trace.black in
  for j = 0 to bh do
    for i = 0 to bw do
      corners.(i + (j * cw)) <- sample ctx cam (float_of_int (b.bx0 + i) -. 0.5) (float_of_int (b.by0 + j) -. 0.5)
    done
  done;
  let s = 1 lsl opts.aa_depth in
  let js = opts.jitter /. float_of_int (s + 1) in
  (* The lattice of the current pixel: a point holds a sample when its stamp is the pixel's number,
     so nothing needs clearing between pixels. *)
  let n = s + 1 in
  let lattice = Array.make (n * n) Trace.black and stamp = Array.make (n * n) 0 and pixel = ref 0 in
  let put i j c =
    lattice.(i + (j * n)) <- c;
    stamp.(i + (j * n)) <- !pixel
  in
  let get i j = lattice.(i + (j * n)) in
  (* lattice point (i, j) at image position (x, y), traced unless this pixel already has it *)
  let take i j x y =
    if stamp.(i + (j * n)) <> !pixel then begin
      let c =
        if js > 0. then sample ctx cam (x +. (Jitter.jx x y *. js)) (y +. (Jitter.jy x y *. js)) else sample ctx cam x y
      in
      ctx.stats.samples <- ctx.stats.samples + 1;
      put i j c
    end
  in
  let far a b = aa_distance enc a b >= thr in
  (* The square of side [step] whose top-left lattice point is (i, j) and whose centre is at image
     position (x, y), [d] from its edges; [level] more subdivisions are allowed. *)
  let rec sub x y d i j step level =
    let c00 = get i j and c01 = get i (j + step) and c10 = get (i + step) j and c11 = get (i + step) (j + step) in
    if level > 0 && (far c00 c01 || far c00 c10 || far c00 c11 || far c01 c10 || far c01 c11 || far c10 c11) then begin
      let h = step / 2 and d2 = d *. 0.5 in
      take i (j + h) (x -. d) y;
      take (i + h) j x (y -. d);
      take (i + step) (j + h) (x +. d) y;
      take (i + h) (j + step) x (y +. d);
      take (i + h) (j + h) x y;
      let q00 = sub (x -. d2) (y -. d2) d2 i j h (level - 1) in
      let q01 = sub (x -. d2) (y +. d2) d2 i (j + h) h (level - 1) in
      let q10 = sub (x +. d2) (y -. d2) d2 (i + h) j h (level - 1) in
      let q11 = sub (x +. d2) (y +. d2) d2 (i + h) (j + h) h (level - 1) in
      mean4 q00 q01 q10 q11
    end
    else mean4 c00 c01 c10 c11
  in
  for y = b.by0 to b.by1 do
    for x = b.bx0 to b.bx1 do
      incr pixel;
      let i = x - b.bx0 and j = y - b.by0 in
      put 0 0 corners.(i + (j * cw));
      put 0 s corners.(i + ((j + 1) * cw));
      put s 0 corners.(i + 1 + (j * cw));
      put s s corners.(i + 1 + ((j + 1) * cw));
      store x y (sub (float_of_int x) (float_of_int y) 0.5 0 0 s (opts.aa_depth - 1))
    done
  done

(* One block: its pixels as r g b triples, row-major. *)
let render_block ctx opts cam enc (b : block) =
  let bw = b.bx1 - b.bx0 + 1 and bh = b.by1 - b.by0 + 1 in
  let out = Float.Array.make (3 * bw * bh) 0. in
  let store x y (c : Trace.result) =
    let i = 3 * (((y - b.by0) * bw) + (x - b.bx0)) in
    Float.Array.set out i c.r;
    Float.Array.set out (i + 1) c.g;
    Float.Array.set out (i + 2) c.b
  in
  (match (opts.antialias, opts.aa_method) with
  | None, _ -> plain_block ctx cam b store
  | Some thr, Non_adaptive -> non_adaptive_block ctx opts cam enc thr b store
  | Some thr, Adaptive -> adaptive_block ctx opts cam enc thr b store);
  out

let blocks opts =
  let a = opts.area and bs = opts.block_size in
  let rec rows y acc =
    if y > a.bottom then List.rev acc
    else
      let rec cols x acc =
        if x > a.right then acc
        else cols (x + bs) ({ bx0 = x; by0 = y; bx1 = min a.right (x + bs - 1); by1 = min a.bottom (y + bs - 1) } :: acc)
      in
      rows (y + bs) (cols a.left acc)
  in
  rows a.top []

(* 256 MB of garbage between collections while rendering *)
let major_budget = 32. *. 1024. *. 1024.

let render opts (sc : Compiled.t) (gamma : Scene.gamma) : Image.t * Stats.t =
  let g = match gamma with Scene.Gamma_off -> 1. | Scene.Working g -> g in
  let inv = 1. /. opts.aa_gamma in
  let enc x = if g = 1. then Float.pow (Float.max x 0.) inv else Float.pow (Float.pow (Float.max x 0.) g) inv in
  let cam = Camera.make sc ~robust:opts.robust ~width:opts.width ~height:opts.height in
  let bl = blocks opts in
  let total = List.length bl in
  (* crand's stream runs through the blocks in order: one worker, as one POV-Ray thread *)
  let workers = if sc.uses_crand then 1 else opts.workers in
  (* One worker renders the blocks in order as POV-Ray's one render thread does, whose shadow
     cache carries from block to block. With more workers (POV-Ray's threads take blocks as they
     come, so which cache a block starts with varies from run to run) every block starts with an
     empty cache, so that the image does not depend on which worker renders which block. The
     isosurfaces' cache of the last missed root search is carried the same way. *)
  let carry = workers = 1 in
  (* Blocks leave garbage in the major heap (their pixel buffers, antialiasing's grids and the
     samples they hold), which the nearly idle major collector (below) would let pile up without
     end in a large image: after every [major_budget] words of it a full collection runs. A
     render of an ordinary size never reaches it. *)
  let collected_at = ref (Gc.quick_stat ()).major_words in
  let bound_garbage ~compact =
    let major = (Gc.quick_stat ()).major_words in
    if major -. !collected_at > major_budget then begin
      if compact then Gc.compact () else Gc.full_major ();
      collected_at := major
    end
  in
  (* Tracing allocates only short-lived values, and the scene stays alive throughout: a major
     collection would only walk the scene (and, in forked workers, copy every page it marks), so
     the major collector is kept almost idle while rendering, in each process from its first block
     on: not before, since the heap grows by [space_overhead] percent of any large allocation (the
     list of two million blocks of a 67,108,864×1 image made into an array would reserve 1.6 GB). *)
  let gc = Gc.get () in
  let quiet = lazy (Gc.set { gc with space_overhead = 10_000 }) in
  (* the context of the worker (of the process: workers are forked before their first block),
     its rooms made once and renewed for each block *)
  let worker = ref None in
  let work (i, b) =
    Lazy.force quiet;
    bound_garbage ~compact:false;
    let stats = Stats.create () in
    let ctx =
      match !worker with
      | None -> Trace.make_ctx ~robust:opts.robust sc stats
      | Some ctx -> Trace.renew_ctx ctx ~carry stats
    in
    worker := Some ctx;
    let px = render_block ctx opts cam enc b in
    (* blocks finish in about this order whichever worker renders them *)
    if opts.progress then Printf.eprintf "\rRendering block %d of %d %!" (i + 1) total;
    (b, px, stats)
  in
  let bl = List.mapi (fun i b -> (i, b)) bl in
  (* each block goes into the image as it comes back (the blocks' pixels are never all held at
     once), and its counts into the statistics; the isosurfaces' sums, which are floats, are
     added up in block order at the end (most blocks have none, and none is kept for them: a
     large allocation here would grow the heap by [space_overhead] times its size). The image is made when the
     first block comes back: worker processes, forked before, do not carry it. *)
  let image = lazy (Image.create opts.width opts.height) in
  let counts = ref (Stats.create ()) in
  let iso_found = ref [] in
  let place i (b, px, (st : Stats.t)) =
    (* blocks read back from worker processes come in heap chunks of their own (unmarshalled),
       which only a compaction gives back *)
    Lazy.force quiet;
    bound_garbage ~compact:(workers > 1);
    let img = Lazy.force image in
    let bw = b.bx1 - b.bx0 + 1 in
    for y = b.by0 to b.by1 do
      for x = b.bx0 to b.bx1 do
        let i = 3 * (((y - b.by0) * bw) + (x - b.bx0)) in
        Image.set img x y (Float.Array.get px i) (Float.Array.get px (i + 1)) (Float.Array.get px (i + 2))
      done
    done;
    if st.iso_found <> [||] then iso_found := (i, st.iso_found) :: !iso_found;
    counts := Stats.merge !counts { st with iso_found = [||] }
  in
  Fun.protect ~finally:(fun () -> Gc.set gc) (fun () -> Pool.iter ~workers work bl place);
  if opts.progress then prerr_string "\r\027[K";
  let stats =
    List.fold_left
      (fun acc (_, found) -> Stats.merge acc { (Stats.create ()) with iso_found = found })
      !counts
      (List.sort (fun (i, _) (j, _) -> compare i j) !iso_found)
  in
  (Lazy.force image, stats)
