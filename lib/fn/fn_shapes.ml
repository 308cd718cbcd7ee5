(* The geometric internal functions of POV-Ray 3.7 (fnintern.cpp): distances to spheres, tori,
   boxes and helices, blobs and ellipsoid blends, meshes, hexagonal tilings, spirals. Each is
   written in the order C evaluates POV-Ray's expression, with its own guards (a point on the
   y axis moved off it before an atan2, the clips of the blobs). Argument array: x, y, z at 0,
   1, 2, then the parameters from 3. *)

let fmin = C_float.fmin
let fmax = C_float.fmax

let pi = Float.pi
let two_pi = 6.283185307179586476925286766560
let deg_to_rad = 0.01745329251994329576

(* the x POV-Ray uses when the point is on the y axis, where atan2 (z, x) is undefined *)
let[@inline] off_axis ~eps x z = if x = 0. && z = 0. then eps else x

(* POV-Ray's fmod(v, 2π) moved into [0, 2π) *)
let[@inline] angle_mod v =
  let th = Float.rem v two_pi in
  if th < 0. then th +. two_pi else th

(* The cross sections of the helices and the spiral: a circle (1), a superellipse of exponent
   2/shape (another shape), a square (0). *)
let[@inline] superellipse u v shape =
  let e = 2. /. shape in
  Float.pow (Float.pow (Float.abs u) e +. Float.pow (Float.abs v) e) (shape *. 0.5)

(* ---------------------------------------------------------------------------------------------- *)
(* Blobs and blends of exponentials *)

let blob a =
  let x = a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  let half = a.(3) *. 0.5 in
  let r = ((x +. half) *. (x +. half) +. y2 +. z2) *. a.(5) *. a.(5) in
  let r = if r > 1. then 1. else r in
  let t = ((x -. half) *. (x -. half) +. y2 +. z2) *. a.(7) *. a.(7) in
  let t = if t > 1. then 1. else t in
  -.((a.(4) *. (1. -. r) *. (1. -. r)) +. (a.(6) *. (1. -. t) *. (1. -. t)))

let blob2 a =
  let x = a.(0) in
  let x2 = x *. x and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  let sep = a.(3) and inv = a.(4) in
  let r = exp (-.(x2 +. y2 +. z2) *. inv) +. exp (-.(((x -. sep) *. (x -. sep)) +. y2 +. z2) *. inv) in
  a.(6) -. (r *. a.(5))

(* The three ellipsoids of f_cross_ellipsoids, f_flange_cover, f_isect_ellipsoids and f_spikes,
   each prolate along one axis: exp (−(…)·inverse size) *)
let[@inline] ellipsoid_x ~ecc ~inv x2 y2 z2 = exp (-.(x2 +. (y2 *. ecc) +. (z2 *. ecc)) *. inv)
let[@inline] ellipsoid_y ~ecc ~inv x2 y2 z2 = exp (-.((x2 *. ecc) +. y2 +. (z2 *. ecc)) *. inv)
let[@inline] ellipsoid_z ~ecc ~inv x2 y2 z2 = exp (-.((x2 *. ecc) +. (y2 *. ecc) +. z2) *. inv)

let ellipsoids combine a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  let ecc = a.(3) and inv = a.(4) in
  let r =
    combine
      (combine (ellipsoid_z ~ecc ~inv x2 y2 z2) (ellipsoid_y ~ecc ~inv x2 y2 z2))
      (ellipsoid_x ~ecc ~inv x2 y2 z2)
  in
  a.(6) -. (r *. a.(5))

let cross_ellipsoids = ellipsoids fmax
let isect_ellipsoids = ellipsoids fmin
let flange_cover = ellipsoids ( +. )

let spikes a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  let ecc = a.(3) and inv = a.(4) in
  let r =
    (exp (-.(x2 +. y2 +. z2) *. a.(6)) *. a.(7))
    -. ellipsoid_z ~ecc ~inv x2 y2 z2 -. ellipsoid_y ~ecc ~inv x2 y2 z2 -. ellipsoid_x ~ecc ~inv x2 y2 z2
  in
  -.r *. a.(5)

let spikes_2d a =
  let x = a.(0) and z = a.(2) in
  -.((a.(3) *. cos (a.(4) *. x) *. cos (a.(5) *. z) *. exp (-.a.(6) *. ((x *. x) +. (z *. z)))) -. a.(1))

(* ---------------------------------------------------------------------------------------------- *)
(* Distances *)

let ellipsoid a =
  sqrt ((a.(0) *. a.(0) *. a.(3) *. a.(3)) +. (a.(1) *. a.(1) *. a.(4) *. a.(4)) +. (a.(2) *. a.(2) *. a.(5) *. a.(5)))

let r a = sqrt ((a.(0) *. a.(0)) +. (a.(1) *. a.(1)) +. (a.(2) *. a.(2)))
let sphere a = -.a.(3) +. r a
let ph a = Float.atan2 (sqrt ((a.(0) *. a.(0)) +. (a.(2) *. a.(2)))) a.(1)
let th a = Float.atan2 a.(0) a.(2)

let torus a =
  let d = sqrt ((a.(0) *. a.(0)) +. (a.(2) *. a.(2))) -. a.(3) in
  -.a.(4) +. sqrt ((d *. d) +. (a.(1) *. a.(1)))

(* f_rounded_box's distance outside the box along one axis: below the lower face, above the
   upper one, 0 between *)
let[@inline] box_excess ~radius ~half v =
  let upper = half -. radius in
  let above = if v < upper then 0. else v -. upper in
  let lower = radius -. half in
  let below = if v > lower then 0. else lower -. v in
  fmax below above

let rounded_box a =
  let radius = a.(3) in
  let dx = box_excess ~radius ~half:a.(4) a.(0)
  and dy = box_excess ~radius ~half:a.(5) a.(1)
  and dz = box_excess ~radius ~half:a.(6) a.(2) in
  -.radius +. sqrt ((dx *. dx) +. (dy *. dy) +. (dz *. dz)) -. 1e-6

let poly4 a =
  let y = a.(1) in
  let y2 = y *. y in
  let t = a.(3) +. (a.(4) *. y) +. (a.(5) *. y2) +. (a.(6) *. y2 *. y) +. (a.(7) *. y2 *. y2) in
  let t = if t < -5. then -5. else t in
  -.t +. sqrt ((a.(0) *. a.(0)) +. (a.(2) *. a.(2)))

let polytubes a =
  let x = a.(0) and y = a.(1) and z = a.(2) and n = a.(3) in
  let y2 = y *. y in
  let radius = a.(4) +. (a.(5) *. y) +. (a.(6) *. y2) +. (a.(7) *. y2 *. y) +. (a.(8) *. y2 *. y2) in
  let step = 2. *. pi /. n in
  let r = ref (-10000.) in
  for i = 0 to C_float.c_int n - 1 do
    let dx = x -. (radius *. sin (step *. float i)) and dz = z -. (radius *. cos (step *. float i)) in
    r := fmax !r (-.sqrt ((dx *. dx) +. (dz *. dz)))
  done;
  -. !r

(* ---------------------------------------------------------------------------------------------- *)
(* Helices, the helical torus, the spiral *)

let helical_torus a =
  let x = a.(0) and y = a.(1) and z = a.(2) in
  let major = a.(3) and minor = a.(8) in
  let r2 = sqrt ((x *. x) +. (z *. z)) in
  let ph = Float.atan2 (off_axis ~eps:0.000001 x z) z in
  let r = sqrt (((r2 -. major) *. (r2 -. major)) +. (y *. y)) in
  let th = angle_mod ((ph *. a.(4)) +. (Float.atan2 (r2 -. major) y *. a.(5))) in
  let groove = Float.atan2 ((th -. pi) *. a.(11)) (r -. minor) in
  let winding = (cos ((groove *. a.(10)) +. (ph *. a.(12))) *. a.(6)) +. a.(7) in
  let outer = a.(7) +. minor -. major -. r2 in
  let th = th -. pi in
  let winding = winding -. fmin (sqrt (((r -. minor) *. (r -. minor)) +. (th *. th *. a.(9)))) (r +. minor) in
  -.fmax outer winding

let helix1 a =
  let x = a.(0) and y = a.(1) and z = a.(2) in
  let n = a.(3) and period = a.(4) and major = a.(6) and shape = a.(8) and angle = a.(9) in
  let r = sqrt ((x *. x) +. (z *. z)) in
  let th = Float.atan2 z (off_axis ~eps:0.000001 x z) in
  let th = angle_mod ((th *. n) +. (y *. period *. n)) in
  let z = (th -. pi) /. a.(7) /. (period *. n) in
  let x = r -. major in
  let r2 =
    if shape = 1. then sqrt ((x *. x) +. (z *. z))
    else begin
      let x, z =
        if angle <> 0. then begin
          let c = cos (angle *. deg_to_rad) and s = sin (angle *. deg_to_rad) in
          ((x *. c) -. (z *. s), (x *. s) +. (z *. c))
        end
        else (x, z)
      in
      if shape <> 0. then superellipse x z shape else fmax (Float.abs x) (Float.abs z)
    end
  in
  -.a.(5) +. fmin (major +. r) r2

let helix2 a =
  let t = a.(1) *. a.(4) in
  let c = cos t and s = sin t in
  let dx = a.(0) -. (a.(6) *. c) and dz = a.(2) -. (a.(6) *. s) in
  let x = (dx *. c) +. (dz *. s) and z = (-.dx *. s) +. (dz *. c) in
  let shape = a.(8) in
  if shape = 1. then sqrt ((x *. x) +. (z *. z)) -. a.(5)
  else begin
    let r2 = if shape <> 0. then superellipse x z shape else fmax (Float.abs x) (Float.abs z) in
    r2 -. a.(5)
  end

(* f_spiral: the exponent of its superellipse is 1/(2/shape), not shape/2 as in the helices *)
let spiral a =
  let y = a.(1) and z = a.(2) and gap = a.(3) and shape = a.(8) in
  let r = sqrt ((a.(0) *. a.(0)) +. (z *. z)) in
  let x = off_axis ~eps:0.000001 a.(0) z in
  let r = r +. (gap *. Float.atan2 z x /. two_pi) in
  let r2 = Float.rem r gap -. (gap *. 0.5) in
  let r2 =
    if shape = 1. then sqrt ((r2 *. r2) +. (y *. y))
    else if shape <> 0. then begin
      let e = 2. /. shape in
      Float.pow (Float.pow (Float.abs r2) e +. Float.pow (Float.abs y) e) (1. /. e)
    end
    else fmax (Float.abs r2) (Float.abs y)
  in
  let r = sqrt ((x *. x) +. (y *. y) +. (z *. z)) in
  -.fmin (a.(5) -. r) (a.(4) -. fmin r2 r)

let superellipsoid a =
  let e = a.(3) and n = a.(4) in
  let p = 2. /. e and inv_n = 1. /. n in
  let xy = Float.pow (Float.pow (Float.abs a.(0)) p +. Float.pow (Float.abs a.(1)) p) (e *. inv_n) in
  1. -. Float.pow (xy +. Float.pow (Float.abs a.(2)) (2. *. inv_n)) (n *. 0.5)

(* ---------------------------------------------------------------------------------------------- *)
(* The comma, the mesh, the quantum orbital, the hexagonal tilings *)

let comma a =
  let y = a.(1) and z = a.(2) and s = a.(3) in
  let x = off_axis ~eps:0.0001 a.(0) z in
  let th = Float.atan2 z x in
  let r = sqrt (((x +. (s *. 0.25)) *. (x +. (s *. 0.25))) +. (z *. z)) in
  let t = (cos (th *. 0.5) *. s *. 0.5) -. sqrt (((r -. (s *. 0.75)) *. (r -. (s *. 0.75))) +. (y *. y)) in
  let t = fmin z t in
  let r = (s *. 0.5) -. sqrt (((x -. (s *. 0.5)) *. (x -. (s *. 0.5))) +. (z *. z) +. (y *. y)) in
  -.fmax t r

(* one family of f_mesh1's threads: the distance to the nearest along [u] (period 2·[gap]), the
   thread waving in y by [wave] *)
let[@inline] mesh_thread ~gap ~thick ~yscale u y wave =
  let r = Float.rem u (gap *. 2.) in
  let r = if r < 0. then r +. (gap *. 2.) else r in
  let r = Float.abs (r -. gap) *. thick in
  let r2 = (y +. wave) *. yscale in
  -.sqrt ((r2 *. r2) +. (r *. r))

let mesh1 a =
  let x = a.(0) and y = a.(1) and z = a.(2) in
  let gx = a.(3) and gz = a.(4) and thick = a.(5) and amp = a.(6) and yscale = a.(7) in
  let th = pi /. gx and ph = pi /. gz in
  let t = mesh_thread ~gap:gx ~thick ~yscale x y (-.(cos (z *. ph) *. amp)) in
  let t = fmax (mesh_thread ~gap:gx ~thick ~yscale (x -. gx) y (cos (z *. ph) *. amp)) t in
  let t = fmax (mesh_thread ~gap:gz ~thick ~yscale z y (cos (x *. th) *. amp)) t in
  -.fmax (mesh_thread ~gap:gz ~thick ~yscale (z -. gz) y (-.(cos (x *. th) *. amp))) t

let quantum a =
  let y = a.(1) and z = a.(2) in
  let x = off_axis ~eps:1e-6 a.(0) z in
  let r = sqrt ((x *. x) +. (z *. z)) in
  let th = cos (Float.atan2 r y) in
  let r = sqrt ((r *. r) +. (y *. y)) *. 2. in
  let t = r *. r *. exp (-.r *. 0.33333333) *. ((3. *. th *. th) -. 1.) in
  ((t *. t) -. 12.0) *. -0.1

(* the nearest hexagon centre's offset (|x|, |y|) in the tiling of f_hex_x and f_hex_y, and
   whether it lies below 30° from the x axis *)
let sqrt3 = sqrt 3.0
let half_sqrt3 = sqrt3 /. 2.
let cos_60 = cos (pi /. 3.)
let sin_60 = sin (pi /. 3.)

let[@inline] hex_x1 a = Float.abs (Float.rem (Float.abs a.(0)) sqrt3 -. half_sqrt3)
let[@inline] hex_y1 a = Float.abs (Float.rem (Float.abs a.(1)) 3. -. 1.5)

let hex select a =
  let x1 = hex_x1 a and y1 = hex_y1 a in
  let x2 = half_sqrt3 -. x1 and y2 = 1.5 -. y1 in
  let far = (x1 *. x1) +. (y1 *. y1) > (x2 *. x2) +. (y2 *. y2) in
  let x1 = if far then x2 else x1 and y1 = if far then y2 else y1 in
  select (Float.atan2 y1 x1 < pi /. 6.) x1 y1

let hex_x = hex (fun low x1 y1 -> if low then x1 else (cos_60 *. x1) +. (sin_60 *. y1))
let hex_y = hex (fun low x1 y1 -> if low then y1 else Float.abs ((-.sin_60 *. x1) +. (cos_60 *. y1)))

(* ---------------------------------------------------------------------------------------------- *)

let find k =
  match k with
  | 6 -> Some blob
  | 7 -> Some blob2
  | 9 -> Some comma
  | 10 -> Some cross_ellipsoids
  | 17 -> Some ellipsoid
  | 19 -> Some flange_cover
  | 24 -> Some helical_torus
  | 25 -> Some helix1
  | 26 -> Some helix2
  | 27 -> Some hex_x
  | 28 -> Some hex_y
  | 32 -> Some isect_ellipsoids
  | 40 -> Some mesh1
  | 47 -> Some ph
  | 51 -> Some poly4
  | 52 -> Some polytubes
  | 53 -> Some quantum
  | 57 -> Some r
  | 60 -> Some rounded_box
  | 61 -> Some sphere
  | 62 -> Some spikes
  | 63 -> Some spikes_2d
  | 64 -> Some spiral
  | 68 -> Some superellipsoid
  | 69 -> Some th
  | 70 -> Some torus
  | _ -> None
