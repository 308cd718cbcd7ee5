(* The complex functions a hypercomplex julia fractal iterates (POV-Ray's math/hcmplx.cpp,
   Complex_Exp … Complex_Pwr), each a pair of doubles in, a pair out, in POV-Ray's operation order.
   Where POV-Ray leaves its result unwritten (a division by zero) the result here is 0. *)

type func = Exp | Ln | Sin | Asin | Cos | Acos | Tan | Atan | Sinh | Asinh | Cosh | Acosh | Tanh | Atanh | Pwr

let mult ax ay bx by = ((ax *. bx) -. (ay *. by), (ax *. by) +. (ay *. bx))

let div ax ay bx by =
  let m = (bx *. bx) +. (by *. by) in
  if m = 0. then (0., 0.)
  else
    let yx = bx /. m and yy = -.by /. m in
    ((ax *. yx) -. (ay *. yy), (ax *. yy) +. (ay *. yx))

let ln x y = (log (sqrt ((x *. x) +. (y *. y))), Float.atan2 y x)

let csqrt x y =
  if x = 0. && y = 0. then (0., 0.)
  else
    let mag = sqrt (sqrt ((x *. x) +. (y *. y))) in
    let theta = Float.atan2 y x /. 2. in
    (mag *. cos theta, mag *. sin theta)

(* arctanh z = ½ ln((1 + z)/(1 − z)), with POV-Ray's special cases on the axes *)
let atanh_c x y =
  if x = 0. then (0., atan y)
  else if Float.abs x = 1. && y = 0. then (0., 0.)
  else if Float.abs x < 1. && y = 0. then (log ((1. +. x) /. (1. -. x)) /. 2., 0.)
  else
    let qx, qy = div (1. +. x) y (1. -. x) (-.y) in
    let lx, ly = ln qx qy in
    (0.5 *. lx, 0.5 *. ly)

let apply f ~ex ~ey x y =
  match f with
  | Exp ->
      let e = exp x in
      (e *. cos y, e *. sin y)
  | Ln -> ln x y
  | Sin -> (sin x *. cosh y, cos x *. sinh y)
  | Sinh -> (sinh x *. cos y, cosh x *. sin y)
  | Cos -> (cos x *. cosh y, -.sin x *. sinh y)
  | Cosh -> (cosh x *. cos y, sinh x *. sin y)
  | Asin ->
      (* −i ln(i z + √(1 − z²)) *)
      let sx, sy = mult x y x y in
      let rx, ry = csqrt (1. -. sx) (-.sy) in
      let lx, ly = ln (rx +. -.y) (ry +. x) in
      (ly, -.lx)
  | Acos ->
      let sx, sy = mult x y x y in
      let rx, ry = csqrt (sx -. 1.) sy in
      let lx, ly = ln (rx +. x) (ry +. y) in
      (ly, -.lx)
  | Asinh ->
      let sx, sy = mult x y x y in
      let rx, ry = csqrt (sx +. 1.) sy in
      ln (rx +. x) (ry +. y)
  | Acosh ->
      let sx, sy = mult x y x y in
      let rx, ry = csqrt (sx -. 1.) sy in
      ln (x +. rx) (y +. ry)
  | Atanh -> atanh_c x y
  | Atan ->
      if x = 0. && y = 0. then (0., 0.)
      else if x <> 0. && y = 0. then (atan x, 0.)
      else if x = 0. then
        let ax, ay = atanh_c y 0. in
        (-.ay, ax)
      else
        (* i/2 ln((1 − iz)/(1 + iz)) *)
        let t0x = -.y and t0y = x in
        let qx, qy = div (1. -. t0x) (-.t0y) (1. +. t0x) t0y in
        let lx, ly = ln qx qy in
        (-.ly *. 0.5, 0.5 *. lx)
  | Tan ->
      let x = 2. *. x and y = 2. *. y in
      let d = cos x +. cosh y in
      if d = 0. then (0., 0.) else (sin x /. d, sinh y /. d)
  | Tanh ->
      let x = 2. *. x and y = 2. *. y in
      let d = cosh x +. cos y in
      if d = 0. then (0., 0.) else (sinh x /. d, sin y /. d)
  | Pwr ->
      if x = 0. && y = 0. then (0., 0.)
      else
        let lx, ly = ln x y in
        let tx, ty = mult lx ly ex ey in
        let e = if tx < -690. then 0. else exp tx in
        (e *. cos ty, e *. sin ty)

(* Hypercomplex arithmetic: the product (HMult), the square (HSqr), the reciprocal (HReciprocal,
   None where the determinant is 0) and a function applied through the duplex form (HFunc). *)

let[@inline] hmult x1 y1 z1 w1 x2 y2 z2 w2 =
  ( (x1 *. x2) -. (y1 *. y2) -. (z1 *. z2) +. (w1 *. w2),
    (y1 *. x2) +. (x1 *. y2) -. (w1 *. z2) -. (z1 *. w2),
    (z1 *. x2) -. (w1 *. y2) +. (x1 *. z2) -. (y1 *. w2),
    (w1 *. x2) +. (z1 *. y2) +. (y1 *. z2) +. (x1 *. w2) )

let[@inline] hsqr x y z w =
  ((x *. x) -. (y *. y) -. (z *. z) +. (w *. w), 2.0 *. ((x *. y) -. (z *. w)), 2.0 *. ((z *. x) -. (w *. y)), 2.0 *. ((w *. x) +. (z *. y)))

let hreciprocal x y z w =
  let det = (((x -. w) *. (x -. w)) +. ((y +. z) *. (y +. z))) *. (((x +. w) *. (x +. w)) +. ((y -. z) *. (y -. z))) in
  if det = 0. then None
  else
    let m = (x *. x) +. (y *. y) +. (z *. z) +. (w *. w) in
    let xt = (x *. w) -. (y *. z) in
    Some
      ( ((x *. m) -. (2. *. w *. xt)) /. det,
        ((-.y *. m) -. (2. *. z *. xt)) /. det,
        ((-.z *. m) -. (2. *. y *. xt)) /. det,
        ((w *. m) -. (2. *. x *. xt)) /. det )

let hfunc f ~ex ~ey x y z w =
  let rax, ray = apply f ~ex ~ey (x -. w) (y +. z) in
  let rbx, rby = apply f ~ex ~ey (x +. w) (y -. z) in
  (0.5 *. (rax +. rbx), 0.5 *. (ray +. rby), 0.5 *. (ray -. rby), 0.5 *. (rbx -. rax))
