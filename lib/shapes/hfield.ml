(* The height field: POV-Ray 3.7's HField (shape/hfield.cpp). The field lives in its own space,
   one unit per image pixel in x and z and one per height step (0 … 65535) in y; the parser's
   scaling transform and every modifier map it to the world. *)

open Bigarray

type f32s = (float, float32_elt, c_layout) Array1.t

type field = {
  width : int;  (* vertices along x (the image's width) *)
  height : int;  (* vertices along z (the image's height) *)
  map : f32s;  (* the heights (integers, exact in single precision), z·width + x, z = 0 the image's bottom row *)
  min_y : int;
  max_y : int;
  water : float;  (* 65536 · water_level as parsed (bounding_corner1[Y] before Compute_HField) *)
  lo_y : float;  (* bounding_corner1[Y]: max(min_y, water) − HFIELD_OFFSET *)
  hi_y : float;  (* bounding_corner2[Y]: max_y + HFIELD_OFFSET *)
  smooth : bool;
  hierarchy : bool;
  nbx : int;  (* block_max_x *)
  nbz : int;  (* block_max_z *)
  wbx : int;  (* block_width_x *)
  wbz : int;  (* block_width_z *)
  blocks : int array;  (* 4 per block (row-major by z): xmin, xmax, zmin, zmax *)
  block_y : float array;  (* 2 per block: ymin, ymax *)
  sealed : bool;
}

type t = { field : field; tr : Transform.t }

let hfield_offset = 0.001
let hfield_tolerance = 1.0e-6
let epsilon = Precision.epsilon
let bound_huge = 2e10

let[@inline] get f x z = Array1.unsafe_get f.map ((z * f.width) + x)

(* C++'s std::min and std::max (no C call, unlike Float.min) *)
let[@inline] fmin (a : float) b = if b < a then b else a
let[@inline] fmax (a : float) b = if a < b then b else a

(* ---------------------------------------------------------------------------------------------- *)
(* Building the field (Compute_HField, smooth_height_field, build_hfield_blocks) *)

(* HField::normalize of (x, y, z) into [out]: the vector over its length, or <0, 1, 0> for a
   length within EPSILON *)
let[@inline] normalize_into out x y z =
  let len = sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
  if Float.abs len > epsilon then begin
    let k = 1. /. len in
    out.(0) <- x *. k;
    out.(1) <- y *. k;
    out.(2) <- z *. k
  end
  else begin
    out.(0) <- 0.;
    out.(1) <- 1.;
    out.(2) <- 0.
  end

(* smooth_height_field: each vertex's normal is the sum of the unit normals of the (up to four)
   triangles of its neighbours, each turned upwards, normalised and stored as shorts *)
(* add_single_normal: adds the upward unit normal of the triangle (x0, z0), (x1, z1), (x2, z2) to
   [sum] and is 1 when the triangle is within the field, else 0 (a function of its own, so that its
   floats stay unboxed) *)
let add_normal (map : f32s) width xsize zsize sum nt x0 z0 x1 z1 x2 z2 =
  if x0 < 0 || z0 < 0 || x1 < 0 || z1 < 0 || x2 < 0 || z2 < 0 || x0 > xsize || z0 > zsize || x1 > xsize || z1 > zsize || x2 > xsize
     || z2 > zsize
  then 0
  else begin
    let h x z = Array1.unsafe_get map ((z * width) + x) [@@inline] in
    let v0x = float_of_int x0 and v0y = h x0 z0 and v0z = float_of_int z0 in
    let t0x = float_of_int x2 -. v0x and t0y = h x2 z2 -. v0y and t0z = float_of_int z2 -. v0z in
    let t1x = float_of_int x1 -. v0x and t1y = h x1 z1 -. v0y and t1z = float_of_int z1 -. v0z in
    (* Nt = t0 × t1, normalised, turned upwards (times −1) *)
    normalize_into nt ((t0y *. t1z) -. (t0z *. t1y)) ((t0z *. t1x) -. (t0x *. t1z)) ((t0x *. t1y) -. (t0y *. t1x));
    if nt.(1) < 0. then for a = 0 to 2 do nt.(a) <- nt.(a) *. -1. done;
    for a = 0 to 2 do sum.(a) <- sum.(a) +. nt.(a) done;
    1
  end

(* the normal of vertex (j, i), stored into [out] (three floats at 3 · (i · width + j)) *)
let vertex_normal (map : f32s) width height (out : f32s) j i =
  let xsize = width - 1 and zsize = height - 1 in
  let sum = [| 0.; 0.; 0. |] and nt = [| 0.; 0.; 0. |] in
  (* in this order: the sum's rounding depends on it *)
  let k1 = add_normal map width xsize zsize sum nt j i (j + 1) i j (i + 1) in
  let k2 = add_normal map width xsize zsize sum nt j i j (i + 1) (j - 1) i in
  let k3 = add_normal map width xsize zsize sum nt j i (j - 1) i j (i - 1) in
  let k4 = add_normal map width xsize zsize sum nt j i j (i - 1) (j + 1) i in
  if k1 + k2 + k3 + k4 = 0 then failwith "Failed to find any normals at.";
  normalize_into nt sum.(0) sum.(1) sum.(2);
  let o = 3 * ((i * width) + j) in
  (* (short)(32767·N): truncated *)
  for a = 0 to 2 do Array1.unsafe_set out (o + a) (float_of_int (int_of_float (32767. *. nt.(a)))) done

(* The worker's vertex normals of field [f], each made when it is first asked for
   ([vertex_normal]): NaN until then. POV-Ray makes them all when the field is built; a render
   needs those of the cells its rays meet, which in a large field seen from near are far fewer, so
   each worker keeps its own, made as its rays need them ({!Scratch.vertex_normals}). *)
let rec vertex_normals_in (w : Scratch.t) f = function
  | (map, normals) :: rest -> if map == f.map then normals else vertex_normals_in w f rest
  | [] ->
      let normals = Array1.create float32 c_layout (3 * f.width * f.height) in
      Array1.fill normals Float.nan;
      w.vertex_normals.fields <- (f.map, normals) :: w.vertex_normals.fields;
      normals

(* looked up without an option allocated per normal *)
let vertex_normals (w : Scratch.t) f = vertex_normals_in w f w.vertex_normals.fields

(* build_hfield_blocks: about √n blocks along each axis, each with the height range of its
   vertices (water included) widened by HFIELD_OFFSET; one block without the hierarchy *)
let blocks_of ~hierarchy width height (map : f32s) lo_y hi_y =
  let max_x = width - 2 and max_z = height - 2 in
  let root n = if n < 0 then 1 else max 1 (int_of_float (sqrt (float_of_int n))) in
  let nx = root max_x and nz = root max_z in
  let wx = int_of_float (Float.ceil (float_of_int (max_x + 2) /. float_of_int nx)) in
  let wz = int_of_float (Float.ceil (float_of_int (max_z + 2) /. float_of_int nz)) in
  let nx = if nx * wx < max_x + 2 then nx + 1 else nx in
  let nz = if nz * wz < max_z + 2 then nz + 1 else nz in
  if (not hierarchy) || (nx = 1 && nz = 1) then
    (* block_width_z is max_y + 2 there (a slip of POV-Ray's), never used with one block *)
    (1, 1, max_x + 2, max_z + 2, [| 0; max_x; 0; max_z |], [| lo_y; hi_y |])
  else begin
    let blocks = Array.make (4 * nx * nz) 0 and ys = Array.make (2 * nx * nz) 0. in
    for z = 0 to nz - 1 do
      for x = 0 to nx - 1 do
        let xmin = x * wx and zmin = z * wz in
        let xmax = min (((x + 1) * wx) - 1) max_x and zmax = min (((z + 1) * wz) - 1) max_z in
        let ymin = ref bound_huge and ymax = ref (-.bound_huge) in
        for i = xmin to xmax + 1 do
          for j = zmin to zmax + 1 do
            let y = Array1.unsafe_get map ((j * width) + i) in
            ymin := fmin !ymin y;
            ymax := fmax !ymax y
          done
        done;
        let b = (z * nx) + x in
        blocks.(4 * b) <- xmin;
        blocks.((4 * b) + 1) <- xmax;
        blocks.((4 * b) + 2) <- zmin;
        blocks.((4 * b) + 3) <- zmax;
        ys.(2 * b) <- fmax !ymin lo_y -. hfield_offset;
        ys.((2 * b) + 1) <- !ymax +. hfield_offset
      done
    done;
    (nx, nz, wx, wz, blocks, ys)
  end

let make ~width ~height ~heights ~water ~smooth =
  let map = Array1.create float32 c_layout (width * height) in
  Array.iteri (fun i h -> Array1.unsafe_set map i (float_of_int h)) heights;
  let min_y = Array.fold_left (fun m (h : int) -> if h < m then h else m) 65535 heights in
  let max_y = Array.fold_left (fun m (h : int) -> if h > m then h else m) 0 heights in
  let lo_y = fmax (float_of_int min_y) water -. hfield_offset in
  let hi_y = float_of_int max_y +. hfield_offset in
  (* a vertex has no normal only when the field is one vertex wide or deep, which is refused at
     once, as POV-Ray does *)
  if smooth && (width < 2 || height < 2) then failwith "Failed to find any normals at.";
  let nbx, nbz, wbx, wbz, blocks, block_y = blocks_of ~hierarchy:true width height map lo_y hi_y in
  { width; height; map; min_y; max_y; water; lo_y; hi_y; smooth; hierarchy = true; nbx; nbz; wbx; wbz; blocks; block_y; sealed = false }

let with_hierarchy f on =
  if f.sealed || on = f.hierarchy then f
  else
    let nbx, nbz, wbx, wbz, blocks, block_y = blocks_of ~hierarchy:on f.width f.height f.map f.lo_y f.hi_y in
    { f with hierarchy = on; nbx; nbz; wbx; wbz; blocks; block_y }

let seal f = { f with sealed = true }

(* Parse_HField's scaling: the field's <width − 1, 65536, height − 1> becomes the unit cube *)
let scaling f = Transform.scale (Vec.make (1. /. float_of_int (f.width - 1)) (1. /. 65536.) (1. /. float_of_int (f.height - 1)))

(* ---------------------------------------------------------------------------------------------- *)
(* Intersection *)

(* One ray's walk: the ray in field space, the depth limits, and where its hits go: the nearest
   (a top-level height field stops at the first cell hit) or every one pushed as CSG hits. *)
type walk = {
  f : field;
  ox : float;
  oy : float;
  oz : float;
  dx : float;
  dy : float;
  dz : float;
  mutable mindist : float;
  mutable maxdist : float;
  all : bool;  (* IS_CHILD_OBJECT: every cell is walked and every hit kept *)
  w : Scratch.t;
  id : int;
  wo : Vec.t;  (* the world ray, for the hit points *)
  wd : Vec.t;
  lo : float;
  mutable best : float;
  mutable bpart : int;
  mutable n : int;
}

(* a hit on triangle [tri] of cell (x, z) *)
let found r depth x z tri =
  let part = (2 * ((z * r.f.width) + x)) + tri in
  if r.all then r.n <- Scratch.push_ray r.w r.n r.lo depth part r.id r.wo r.wd
  else if depth >= r.lo && depth <= r.best then begin
    (* the stack is read from its top, a strictly nearer depth kept: the last of equals wins *)
    r.best <- depth;
    r.bpart <- part
  end

(* triangle: triangle [part] (0 the one at corner (x, z), 1 the one at (x + 1, z + 1)) of cell
   (x, z) at ([fx], [fz]), its corner's height [y], the other two corners' heights between [min23]
   and [max23]: tried when its height range meets [height1, height2]; its plane through
   ([px], [y], [pz]) with normal <[nx], 1, [nz]>; a hit inside the triangle is recorded *)
let[@inline] triangle r x z fx fz height1 height2 y min23 max23 nx nz px pz part =
  if fmax y max23 >= height1 && fmin y min23 <= height2 then begin
    let stats = r.w.stats in
    Stats.test stats Stats.hfield_triangle;
    let dot = (nx *. r.dx) +. r.dy +. (nz *. r.dz) in
    if dot > epsilon || dot < -.epsilon then begin
      let depth = ((nx *. (px -. r.ox)) +. (y -. r.oy) +. (nz *. (pz -. r.oz))) /. dot in
      if depth >= r.mindist && depth <= r.maxdist then begin
        let s = r.ox +. (depth *. r.dx) -. fx and t = r.oz +. (depth *. r.dz) -. fz in
        let inside =
          if part = 0 then s >= -0.0001 && t >= -0.0001 && s +. t <= 1.0001 else s <= 1.0001 && t <= 1.0001 && s +. t >= 0.9999
        in
        if inside then begin
          Stats.hit stats Stats.hfield_triangle;
          found r depth x z part;
          true
        end
        else false
      end
      else false
    end
    else false
  end
  else false

(* intersect_pixel: the cell's two triangles, each tried when its height range meets the ray's
   [height1, height2] over the cell *)
let intersect_pixel r x z height1 height2 =
  let f = r.f in
  let stats = r.w.stats in
  Stats.test stats Stats.hfield_cell;
  (* clamped to the last cell; below 0 (never reached by POV-Ray's walk) to the first *)
  let z = if z > f.height - 2 then f.height - 2 else if z < 0 then 0 else z in
  let x = if x > f.width - 2 then f.width - 2 else if x < 0 then 0 else x in
  let y1 = get f x z and y2 = get f (x + 1) z and y3 = get f x (z + 1) and y4 = get f (x + 1) (z + 1) in
  let min23 = if y2 < y3 then y2 else y3 and max23 = if y2 < y3 then y3 else y2 in
  let min_height = fmin (fmin y1 y4) min23 and max_height = fmax (fmax y1 y4) max23 in
  if max_height < height1 || min_height > height2 then false
  else begin
    Stats.hit stats Stats.hfield_cell;
    let fx = float_of_int x and fz = float_of_int z in
    (* the first triangle: (x, y1, z) with N = <y1 − y2, 1, y1 − y3> *)
    let hit1 = triangle r x z fx fz height1 height2 y1 min23 max23 (y1 -. y2) (y1 -. y3) fx fz 0 in
    (* the second: (x + 1, y4, z + 1) with N = <y3 − y4, 1, y2 − y4> *)
    let hit2 = triangle r x z fx fz height1 height2 y4 min23 max23 (y3 -. y4) (y2 -. y4) (fx +. 1.) (fz +. 1.) 1 in
    hit1 || hit2
  end

let[@inline] sign x = if x >= 0. then 1 else -1

(* test_cell: [intersect_pixel] on the cell whose coordinates along the driving and the other axis
   are [major] and [minor] *)
let[@inline] test_cell r x_drives major minor y1 y2 =
  if x_drives then intersect_pixel r major minor y1 y2 else intersect_pixel r minor major y1 y2

(* dda_walk: the cells from cell ([major], [minor]) along the ray, one step along the driving axis
   (the ray's direction [dmajor] along it, [major0] the start's fraction of its cell) at a time,
   crossing into the next row of the other axis ([dminor], [minor0]) where the error term says so;
   [x_drives] tells which axis drives; the walk stays within [majlo..majhi], [minlo..minhi] and
   the ray's near height within [ylo..yhi] *)
let[@inline] dda_walk r x_drives sy dmajor dminor major0 minor0 major minor majlo majhi minlo minhi ylo yhi =
  let found = ref false and stop = ref false in
  let major = ref major and minor = ref minor in
  let signmaj = sign dmajor and signmin = sign dminor in
  let delta = Float.abs (dminor /. dmajor) in
  let error =
    ref
      (if dmajor >= 0. then if dminor >= 0. then minor0 +. (delta *. (1.0 -. major0)) -. 1.0 else -.(minor0 -. (delta *. (1.0 -. major0)))
       else if dminor >= 0. then minor0 +. (delta *. major0) -. 1.0
       else -.(minor0 -. (delta *. major0)))
  in
  let deltay = r.dy /. Float.abs dmajor in
  let neary = ref (if dmajor >= 0. then sy -. (major0 *. deltay) else sy -. ((1.0 -. major0) *. deltay)) in
  let fary = ref (!neary +. deltay) in
  let continue = ref true in
  while !continue do
    let y1 = if !neary < !fary then !neary else !fary and y2 = if !neary < !fary then !fary else !neary in
    if test_cell r x_drives !major !minor y1 y2 then if r.all then found := true else stop := true;
    if !stop then continue := false
    else begin
      let broke = ref false in
      if !error > epsilon then begin
        minor := !minor + signmin;
        if !minor < minlo || !minor > minhi then broke := true
        else begin
          if test_cell r x_drives !major !minor y1 y2 then if r.all then found := true else stop := true;
          error := !error -. 1.
        end
      end
      else if !error > -.epsilon then begin
        minor := !minor + signmin;
        error := !error -. 1.
      end;
      if !broke || !stop then continue := false
      else begin
        major := !major + signmaj;
        error := !error +. delta;
        neary := !fary;
        fary := !fary +. deltay;
        continue := !neary >= ylo && !neary <= yhi && !major >= majlo && !major <= majhi && !minor >= minlo && !minor <= minhi
      end
    end
  done;
  !stop || !found

(* dda_traversal: the cells of block [b] along the ray from [start], stepping along the axis the
   ray moves most along and crossing into the next row where the error term says so *)
let dda_traversal r sx sy sz b =
  let f = r.f in
  let max_x = f.width - 2 and max_z = f.height - 2 in
  let xmin = f.blocks.(4 * b) and xmax = min (f.blocks.((4 * b) + 1) + 1) max_x in
  let zmin = f.blocks.((4 * b) + 2) and zmax = min (f.blocks.((4 * b) + 3) + 1) max_z in
  let ymin = fmin sy f.block_y.(2 * b) -. epsilon and ymax = fmax sy f.block_y.((2 * b) + 1) +. epsilon in
  (* a start outside the block by a rounding error is moved onto it; by more, the ray is given up
     (POV-Ray's "Illegal grid value in dda_traversal()") *)
  let legal p lo hi =
    if p < float_of_int lo then if p < float_of_int lo -. hfield_offset then nan else float_of_int lo
    else if p > float_of_int hi +. 1.0 -. epsilon then if p > float_of_int hi +. 1.0 +. epsilon then nan else float_of_int hi +. 1.0 -. epsilon
    else p
  in
  let px = legal sx xmin xmax in
  let pz = if Float.is_nan px then nan else legal sz zmin zmax in
  if Float.is_nan px || Float.is_nan pz then false
  else begin
    let x0 = px -. Float.floor px and z0 = pz -. Float.floor pz in
    if Float.abs r.dx >= Float.abs r.dz then
      (* x drives *)
      dda_walk r true sy r.dx r.dz x0 z0 (int_of_float px) (int_of_float pz) xmin xmax zmin zmax ymin ymax
    else
      (* z drives; its height test is an epsilon wider *)
      dda_walk r false sy r.dz r.dx z0 x0 (int_of_float pz) (int_of_float px) zmin zmax xmin xmax (ymin -. epsilon)
        (ymax +. epsilon)
  end

(* block_traversal: a vertical ray tests its one cell; a field of one block is walked cell by
   cell; otherwise the blocks the ray crosses are walked, each one's cells walked when the ray's
   height over the block meets the block's height range *)
let block_traversal r sx sy sz =
  let f = r.f in
  let dx = r.dx and dy = r.dy and dz = r.dz in
  let maxdv = if dx > dz then dx else dz in
  if Float.abs dx < epsilon && Float.abs dz < epsilon then begin
    let fary = if dy >= 0. then 65536.0 else 0.0 in
    intersect_pixel r (int_of_float sx) (int_of_float sz) (fmin sy fary) (fmax sy fary)
  end
  else if f.nbx <= 1 && f.nbz <= 1 then dda_traversal r sx sy sz 0
  else begin
    let xmax = f.nbx and zmax = f.nbz in
    let ymin = float_of_int f.min_y -. epsilon and ymax = float_of_int f.max_y +. epsilon in
    let dx_zero = Float.abs dx < epsilon and dz_zero = Float.abs dz < epsilon in
    let signx = sign dx and signz = sign dz in
    let x = ref (int_of_float (sx /. float_of_int f.wbx)) and z = ref (int_of_float (sz /. float_of_int f.wbz)) in
    let nx_ = ref sx and ny_ = ref sy and nz_ = ref sz in
    let neary = ref sy in
    let found = ref false and stop = ref false and continue = ref true in
    let stats = r.w.stats in
    while !continue do
      Stats.test stats Stats.hfield_block;
      let b = (!z * f.nbx) + !x in
      let k1 =
        if dx_zero then bound_huge
        else if signx >= 0 then (float_of_int f.blocks.((4 * b) + 1) +. 1.0 -. r.ox) /. dx
        else (float_of_int f.blocks.(4 * b) -. r.ox) /. dx
      in
      let k2 =
        if dz_zero then bound_huge
        else if signz >= 0 then (float_of_int f.blocks.((4 * b) + 3) +. 1.0 -. r.oz) /. dz
        else (float_of_int f.blocks.((4 * b) + 2) -. r.oz) /. dz
      in
      let dist, nx, nz =
        if dz_zero || ((not dx_zero) && k1 < k2 -. (epsilon /. maxdv) && k1 > 0.0) then (k1, !x + signx, !z)
        else if dz_zero || ((not dx_zero) && k1 < k2 +. (epsilon /. maxdv) && k1 > 0.0) then (k1, !x + signx, !z + signz)
        else (k2, !x, !z + signz)
      in
      let fx = r.ox +. (dist *. dx) and fy = r.oy +. (dist *. dy) and fz = r.oz +. (dist *. dz) in
      let y1 = if !neary < fy then !neary else fy and y2 = if !neary < fy then fy else !neary in
      if y1 <= f.block_y.((2 * b) + 1) +. epsilon && y2 >= f.block_y.(2 * b) -. epsilon then begin
        Stats.hit stats Stats.hfield_block;
        if dda_traversal r !nx_ !ny_ !nz_ b then if r.all then found := true else stop := true
      end;
      if !stop then continue := false
      else begin
        x := nx;
        z := nz;
        nx_ := fx;
        ny_ := fy;
        nz_ := fz;
        neary := fy;
        continue := !x >= 0 && !x < xmax && !z >= 0 && !z < zmax && !neary >= ymin && !neary <= ymax
      end
    done;
    !stop || !found
  end

(* Box::Intersect of the field's box (corners <0, lo_y, 0> and <width − 1, hi_y, height − 1>) in
   field space: the slab crossings, Y and Z keeping the earlier one within CLOSE_TOLERANCE; the
   crossings go to [r.mindist] and [r.maxdist] *)
let box_crossings r =
  let f = r.f in
  let close = 1e-6 in
  let exception Miss in
  try
    let tmin = ref 0.0 and tmax = ref bound_huge in
    let exact c1 c2 p d =
      if d < -.epsilon || d > epsilon then begin
        let exit_c, entry_c = if d < 0. then (c1, c2) else (c2, c1) in
        let t = (exit_c -. p) /. d in
        if t < !tmin then raise Miss;
        if t <= !tmax then tmax := t;
        let t = (entry_c -. p) /. d in
        if t >= !tmin then (if t > !tmax then raise Miss; tmin := t)
      end
      else if p < c1 || p > c2 then raise Miss
    in
    let loose c1 c2 p d =
      if d < -.epsilon || d > epsilon then begin
        let exit_c, entry_c = if d < 0. then (c1, c2) else (c2, c1) in
        let t = (exit_c -. p) /. d in
        if t < !tmin then raise Miss;
        if t <= !tmax -. close then tmax := t;
        let t = (entry_c -. p) /. d in
        if t >= !tmin +. close then (if t > !tmax then raise Miss; tmin := t)
      end
      else if p < c1 || p > c2 then raise Miss
    in
    exact 0. (float_of_int (f.width - 1)) r.ox r.dx;
    loose f.lo_y f.hi_y r.oy r.dy;
    loose 0. (float_of_int (f.height - 1)) r.oz r.dz;
    if !tmax < 1e-6 then false
    else begin
      r.mindist <- !tmin;
      r.maxdist <- !tmax;
      true
    end
  with Miss -> false

(* HField::All_Intersections: the ray brought into field space (not renormalised, so depths are
   world depths), clipped to the field's box from HFIELD_TOLERANCE on, then walked. Counted as
   POV-Ray counts "Height Field": a success is a walk that found a hit, whatever its depth. *)
let walk (w : Scratch.t) t ~all id (o : Vec.t) (d : Vec.t) lo n =
  let stats = w.stats in
  Stats.test stats Stats.hfield;
  Stats.test stats Stats.hfield_box;
  let m = t.tr in
  let r =
    {
      f = t.field;
      ox = (o.x *. m.i00) +. (o.y *. m.i10) +. (o.z *. m.i20) +. m.i30;
      oy = (o.x *. m.i01) +. (o.y *. m.i11) +. (o.z *. m.i21) +. m.i31;
      oz = (o.x *. m.i02) +. (o.y *. m.i12) +. (o.z *. m.i22) +. m.i32;
      dx = (d.x *. m.i00) +. (d.y *. m.i10) +. (d.z *. m.i20);
      dy = (d.x *. m.i01) +. (d.y *. m.i11) +. (d.z *. m.i21);
      dz = (d.x *. m.i02) +. (d.y *. m.i12) +. (d.z *. m.i22);
      mindist = 0.; maxdist = 0.; all; w; id; wo = o; wd = d; lo;
      best = infinity; bpart = -1; n;
    }
  in
  let entered =
    box_crossings r
    && (Stats.hit stats Stats.hfield_box;
        true)
    && (r.mindist >= hfield_tolerance
       ||
       (r.mindist <- hfield_tolerance;
        r.mindist <= r.maxdist))
  in
  if entered then begin
    let sx = r.ox +. (r.mindist *. r.dx) and sy = r.oy +. (r.mindist *. r.dy) and sz = r.oz +. (r.mindist *. r.dz) in
    if block_traversal r sx sy sz then Stats.hit stats Stats.hfield
  end;
  r

let depth (w : Scratch.t) t o d lo =
  let r = walk w t ~all:false 0 o d lo 0 in
  if r.bpart >= 0 then w.part <- r.bpart;
  r.best

let hits (w : Scratch.t) t id o d lo n =
  (walk w t ~all:true id o d lo n).n

(* ---------------------------------------------------------------------------------------------- *)
(* Normal, Inside, boxes *)

(* the unit world normal of triangle [tri] of cell (x, z), as intersect_pixel stores it *)
let flat_normal t x z tri =
  let f = t.field in
  let n =
    if tri = 0 then
      let y1 = get f x z in
      Vec.make (y1 -. get f (x + 1) z) 1.0 (y1 -. get f x (z + 1))
    else
      let y4 = get f (x + 1) (z + 1) in
      Vec.make (get f x (z + 1) -. y4) 1.0 (get f (x + 1) z -. y4)
  in
  Transform.normalize (Transform.normal t.tr n)

(* HField::Normal of a smooth field: the four corner normals of the cell, each by the inverse
   transpose and normalised, blended bilinearly, normalised *)
(* the normal of vertex (i, j) of [t]'s field, from the worker's vertex normals [n] (made first if
   need be), by the inverse transpose and normalised *)
let corner t n i j =
  let f = t.field in
  let o = 3 * ((j * f.width) + i) in
  if Float.is_nan (Array1.unsafe_get n o) then vertex_normal f.map f.width f.height n i j;
  Transform.normalize (Transform.normal t.tr (Vec.make (Array1.unsafe_get n o) (Array1.unsafe_get n (o + 1)) (Array1.unsafe_get n (o + 2))))

let smooth_normal w t (p : Vec.t) =
  let f = t.field in
  let n = vertex_normals w f in
  let q = Transform.inv_point t.tr p in
  let px = min (int_of_float q.x) (f.width - 2) and pz = min (int_of_float q.z) (f.height - 2) in
  let px = max px 0 and pz = max pz 0 in
  let x = q.x -. float_of_int px and z = q.z -. float_of_int pz in
  let n0 = corner t n px pz and n1 = corner t n (px + 1) pz and n2 = corner t n px (pz + 1) and n3 = corner t n (px + 1) (pz + 1) in
  let u = 1.0 -. x and v = 1.0 -. z in
  let blend a0 a1 a2 a3 = (v *. ((u *. a0) +. (x *. a1))) +. (z *. ((u *. a2) +. (x *. a3))) in
  Transform.normalize (Vec.make (blend n0.x n1.x n2.x n3.x) (blend n0.y n1.y n2.y n3.y) (blend n0.z n1.z n2.z n3.z))

let normal w t part p =
  if t.field.smooth || part < 0 then smooth_normal w t p
  else
    let k = part / 2 in
    flat_normal t (k mod t.field.width) (k / t.field.width) (part land 1)

(* HField::Inside, before the inverted flag: below the surface of the triangle above the point
   (heights below the water raised to it), within the field's x and z extent and below its top *)
let inside t (p : Vec.t) =
  let f = t.field in
  let q = Transform.inv_point t.tr p in
  let water = f.lo_y in
  if q.x < 0.0 || q.x >= float_of_int (f.width - 1) || q.z < 0.0 || q.z >= float_of_int (f.height - 1) then false
  else if q.y >= f.hi_y then false
  else if q.y < water then true
  else begin
    let px = int_of_float q.x and pz = int_of_float q.z in
    let x = q.x -. float_of_int px and z = q.z -. float_of_int pz in
    let h i j = fmax (get f i j) water in
    let ox, oy, oz, nx, nz =
      if x +. z < 1.0 then
        let y1 = h px pz and y2 = h (px + 1) pz and y3 = h px (pz + 1) in
        (float_of_int px, y1, float_of_int pz, y1 -. y2, y1 -. y3)
      else
        let px = int_of_float (Float.ceil q.x) and pz = int_of_float (Float.ceil q.z) in
        let y1 = h px pz and y2 = h (px - 1) pz and y3 = h px (pz - 1) in
        (float_of_int px, y1, float_of_int pz, y2 -. y1, y3 -. y1)
    in
    let dot1 = (q.x *. nx) +. q.y +. (q.z *. nz) and dot2 = (ox *. nx) +. oy +. (oz *. nz) in
    dot1 < dot2
  end

let box f = [| 0.; f.lo_y; 0.; float_of_int (f.width - 1); f.hi_y; float_of_int (f.height - 1) |]
let bounds t = Transform.bounds t.tr (box t.field)

let pov_box t =
  let b = box t.field in
  Pov_box.mapped t.tr (Pov_box.of_min_max (Array.sub b 0 3) (Array.sub b 3 3))

(* POV-Ray 3.7's build counts the walk's stages too (HFIELD_EXTRA_STATS) *)
let traits = { Traits.default with name = "height_field" }
