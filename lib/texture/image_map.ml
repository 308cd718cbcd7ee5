(* imageutil.cpp's image_map, image_pattern and bump_map. Coordinates are doubles as POV-Ray's;
   colours single precision (its Colour), interpolated in double and rounded once. *)

open Scene

let f = Precision.f32
let epsilon = Precision.epsilon
let two_pi = 6.283185307179586476925286766560
let pi = 3.1415926535897932384626

(* wrap() of base/types.h: into [0, upper), as fmod but for negative values *)
let wrap v upper =
  let t = Float.rem v upper in
  let t = if t < 0. then t +. upper else t in
  if t >= upper then 0. else t

(* C's (int) cast of a coordinate (truncation toward zero) *)
let c_int v = int_of_float v

(* the angle of (x, z) from the x axis, 0 … 2π (the three mappers share it) *)
let angle x z len =
  if z = 0. then if x > 0. then 0. else pi
  else
    let theta = acos (x /. len) in
    if z < 0. then two_pi -. theta else theta

(* planar_image_map with POV-Ray's fixed gradient <1,-1,0>: x gives u, y gives v *)
let planar b (p : Vec.t) =
  if b.once && (p.x < 0. || p.x > 1.) then None
  else if b.once && (p.y < 0. || p.y > 1.) then None
  else Some (Float.rem (p.x *. b.width) b.width, Float.rem (p.y *. b.height) b.height)

let spherical b (p : Vec.t) =
  let len = sqrt ((p.x *. p.x) +. (p.y *. p.y) +. (p.z *. p.z)) in
  if len = 0. then None
  else
    let x = p.x /. len and y = p.y /. len and z = p.z /. len in
    let phi = 0.5 +. (asin y /. pi) in
    let len = sqrt ((x *. x) +. (z *. z)) in
    let theta = if len = 0. then 0. else angle x z len /. two_pi in
    Some (theta *. b.width, phi *. b.height)

let cylindrical b (p : Vec.t) =
  if b.once && (p.y < 0. || p.y > 1.) then None
  else
    let v = Float.rem (p.y *. b.height) b.height in
    let len = sqrt ((p.x *. p.x) +. (p.y *. p.y) +. (p.z *. p.z)) in
    if len = 0. then None
    else
      let x = p.x /. len and z = p.z /. len in
      let len = sqrt ((x *. x) +. (z *. z)) in
      if len = 0. then None else Some (angle x z len /. two_pi *. b.width, v)

(* torus_image_map, the major radius the gradient's x (1) *)
let torus b (p : Vec.t) =
  let len = sqrt ((p.x *. p.x) +. (p.z *. p.z)) in
  if len = 0. then None
  else
    let theta = 0.0 -. angle p.x p.z len in
    let x = len -. 1.0 in
    let len = sqrt ((x *. x) +. (p.y *. p.y)) in
    let phi = acos (-.x /. len) in
    let phi = if p.y > 0. then two_pi -. phi else phi in
    let theta = theta /. two_pi and phi = phi /. two_pi in
    Some (-.theta *. b.width, phi *. b.height)

(* map_pos: the image coordinates of a point, offset, checked against a [once] image and
   wrapped, y turned upside down; None off the image *)
let map_pos b p =
  let uv = match b.map_type with 1 -> spherical b p | 2 -> cylindrical b p | 5 -> torus b p | _ -> planar b p in
  match uv with
  | None -> None
  | Some (u, v) ->
      let iw = float_of_int b.image.width and ih = float_of_int b.image.height in
      let x = u +. (b.offset_u +. epsilon) and y = v +. (b.offset_v +. epsilon) in
      if b.once && (x >= iw || y >= ih || x < 0. || y < 0.) then None else Some (wrap x iw, wrap (-.y) ih)

(* one pixel (no_interpolation): its colour and palette index (-1 without a palette); a [once]
   image takes the nearest edge pixel for samples off it, a repeated one wraps *)
let pixel b x y =
  let img = b.image in
  let iw = img.width and ih = img.height in
  let ix, iy =
    if b.once then
      ( (if x < 0. then 0 else if x >= float_of_int iw then iw - 1 else c_int x),
        if y < 0. then 0 else if y >= float_of_int ih then ih - 1 else c_int y )
    else (c_int (wrap x (float_of_int iw)), c_int (wrap y (float_of_int ih)))
  in
  let r, g, bl, fi, t = Image_file.rgbft img ix iy in
  if Image_file.is_indexed img then ((r, g, bl, fi, t), Image_file.index img (ix + (iy * iw)))
  else ((r, g, bl, f (fi +. b.all_filter), f (t +. b.all_transmit)), -1)

(* a weighted sum of samples in double, each channel rounded to single precision at the end, and
   the index sum truncated *)
let blend samples =
  let r = ref 0. and g = ref 0. and bl = ref 0. and fi = ref 0. and t = ref 0. and idx = ref 0. in
  List.iter
    (fun (((cr, cg, cb, cf, ct), ci), w) ->
      r := !r +. (cr *. w);
      g := !g +. (cg *. w);
      bl := !bl +. (cb *. w);
      fi := !fi +. (cf *. w);
      t := !t +. (ct *. w);
      idx := !idx +. (float_of_int ci *. w))
    samples;
  ((f !r, f !g, f !bl, f !fi, f !t), c_int !idx)

(* bilinear and norm_dist: the weights of the four pixels around the point *)
let bilinear x y =
  let p = x -. float_of_int (c_int x) and q = y -. float_of_int (c_int y) in
  [| p *. q; (1. -. p) *. q; p *. (1. -. q); (1. -. p) *. (1. -. q) |]

let norm_dist x y =
  let p = x -. float_of_int (c_int x) and q = y -. float_of_int (c_int y) in
  let sq a b = (a *. a) +. (b *. b) in
  let wts = [| 1.0 /. sq (1. -. p) (1. -. q); 1.0 /. sq p (1. -. q); 1.0 /. sq (1. -. p) q; 1.0 /. sq p q |] in
  let sum = ((0. +. wts.(0)) +. wts.(1)) +. wts.(2) +. wts.(3) in
  Array.map (fun w -> w /. sum) wts

let cubic x =
  let p = x -. float_of_int (c_int x) in
  let q = 1. -. p in
  [| -0.5 *. p *. q *. q; 0.5 *. q *. ((q *. ((3. *. p) +. 1.)) +. 1.); 0.5 *. p *. ((p *. ((3. *. q) +. 1.)) +. 1.); -0.5 *. q *. p *. p |]

(* image_colour_at: the colour at image coordinates, by the image's interpolation *)
let colour_at b x y =
  match b.interpolate with
  | 0 -> pixel b x y
  | 3 ->
      let x = x +. 0.5 and y = y +. 0.5 in
      let ix = float_of_int (c_int x) and iy = float_of_int (c_int y) in
      let fx = cubic x and fy = cubic y in
      let samples = ref [] in
      for i = 0 to 3 do
        for j = 0 to 3 do
          samples := (pixel b (ix +. float_of_int i -. 2.) (iy +. float_of_int j -. 2.), fx.(i) *. fy.(j)) :: !samples
        done
      done;
      blend (List.rev !samples)
  | _ ->
      let x = x +. 0.5 and y = y +. 0.5 in
      let ix = float_of_int (c_int x) and iy = float_of_int (c_int y) in
      let w = if b.interpolate = 4 then norm_dist x y else if b.interpolate = 2 then bilinear x y else [| 0.; 0.; 0.; 0. |] in
      blend
        [
          (pixel b ix iy, w.(0));
          (pixel b (ix -. 1.) iy, w.(1));
          (pixel b ix (iy -. 1.), w.(2));
          (pixel b (ix -. 1.) (iy -. 1.), w.(3));
        ]

(* Colour::greyscale of a single-precision colour: double arithmetic, rounded back *)
let greyscale r g bl = f ((0.297 *. r) +. (0.589 *. g) +. (0.114 *. bl))

let colour b q =
  match map_pos b q with
  | None -> ({ Colour.red = 1.; green = 1.; blue = 1.; filter = 0.; transmit = 1. }, false)
  | Some (x, y) ->
      let (r, g, bl, fi, t), _ = colour_at b x y in
      (* premultiplied data is divided back by its alpha for an image_map *)
      let r, g, bl =
        if b.image.premultiplied then
          let alpha = f (1. -. t) in
          if alpha > epsilon then (f (r /. alpha), f (g /. alpha), f (bl /. alpha)) else (r, g, bl)
        else (r, g, bl)
      in
      ({ Colour.red = r; green = g; blue = bl; filter = fi; transmit = t }, true)

let value b q =
  match map_pos b q with
  | None -> 0.
  | Some (x, y) ->
      let (r, g, bl, _, t), index = colour_at b x y in
      let v =
        if index = -1 || b.use <> Use_none then
          match b.use with
          | Use_alpha -> if Image_file.has_transparency b.image then t else r
          | Use_none | Use_colour | Use_index -> greyscale r g bl
        else float_of_int index /. 255.0
      in
      if v < 0. then 0. else if v > 1.0 then 1.0 else v

let cross (ax, ay, az) (bx, by, bz) = ((ay *. bz) -. (az *. by), (az *. bx) -. (ax *. bz), (ax *. by) -. (ay *. bx))
let length (x, y, z) = sqrt ((x *. x) +. (y *. y) +. (z *. z))

let normalise v =
  let x, y, z = v and l = length v in
  (x /. l, y /. l, z /. l)

let bump b amount q (n : Vec.t) =
  match map_pos b q with
  | None -> n
  | Some (x, y) ->
      let iw = float_of_int b.image.width and ih = float_of_int b.image.height in
      let (r1, g1, b1, _, _), i1 = colour_at b x y in
      let x = x -. 1. and y = y +. 1. in
      let x = if x < 0. then x +. iw else if x >= iw then x -. iw else x in
      let y = if y < 0. then y +. ih else if y >= ih then y -. ih else y in
      let (r2, g2, b2, _, _), i2 = colour_at b x y in
      let x = x +. 2.0 in
      let x = if x < 0. then x +. iw else if x >= iw then x -. iw else x in
      let (r3, g3, b3, _, _), i3 = colour_at b x y in
      let h1, h2, h3 =
        if b.use <> Use_none || i1 = -1 || i2 = -1 || i3 = -1 then
          (amount *. greyscale r1 g1 b1, amount *. greyscale r2 g2 b2, amount *. greyscale r3 g3 b3)
        else (amount *. float_of_int i1, amount *. float_of_int i2, amount *. float_of_int i3)
      in
      (* the triangle's corners (0, h1, 0), (−1, h2, 1), (1, h3, 1) and its normal *)
      let xprime = (0. -. -1., h1 -. h2, 0. -. 1.) and yprime = (1. -. -1., h3 -. h2, 1. -. 1.) in
      let bx, by, bz = normalise (cross yprime xprime) in
      (* a frame around the surface normal: x across it in the horizontal, z along it *)
      let yp = (n.x, n.y, n.z) in
      let xp = cross yp (0., 1., 0.) in
      let len = length xp in
      let yp, xp, len =
        if len < epsilon then
          if Float.abs (n.y -. 1.0) < epsilon then ((0., 1., 0.), (1., 0., 0.), 1.0) else ((0., -1., 0.), (1., 0., 0.), 1.0)
        else (yp, xp, len)
      in
      let k = 1.0 /. len in
      let xp = (let a, b, c = xp in (a *. k, b *. k, c *. k)) in
      let zx, zy, zz = normalise (cross xp yp) in
      let xx, xy, xz = xp and yx, yy, yz = yp in
      let xx = xx *. bx and xy = xy *. bx and xz = xz *. bx in
      let yx = yx *. by and yy = yy *. by and yz = yz *. by in
      let zx = zx *. bz and zy = zy *. bz and zz = zz *. bz in
      let tx = xx +. yx and ty = xy +. yy and tz = xz +. yz in
      Vec.make (tx +. (zx *. -1.)) (ty +. (zy *. -1.)) (tz +. (zz *. -1.))

let opaque b = not (b.once || b.has_filter || not (Image_file.is_opaque b.image))

(* material_map: the material a point picks, 0 off the image, else the pixel's palette index or
   its red times 255 (truncated), brought below [count] by a remainder only when above it; one
   past the last (or more) stays on the last *)
let material b q count =
  let n =
    match map_pos b q with
    | None -> 0
    | Some (x, y) ->
        let (r, _, _, _, _), reg = colour_at b x y in
        if reg = -1 then c_int (r *. 255.0) else reg
  in
  let n = if n > count then n mod count else n in
  min n (count - 1)
