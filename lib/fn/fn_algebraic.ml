(* The algebraic surfaces among POV-Ray 3.7's internal functions (fnintern.cpp, internal(0) to
   internal(75)): polynomials in x, y and z, most of them scaled by a field strength and clipped
   to ±10. Each expression is written in the order C evaluates POV-Ray's: + and − from the left,
   each product from the left, integer constants as doubles, so that the results are its doubles.
   Argument array: x, y, z at 0, 1, 2, then the parameters from 3. *)

let fmin = C_float.fmin
let fmax = C_float.fmax

(* min(10, max(strength·r, −10)), the clip of almost every surface here *)
let[@inline] clip10 strength r = fmin 10. (fmax (strength *. r) (-10.))

(* min(limit, max(strength·r, −limit)), the clip of the algebraic cylinders *)
let[@inline] clip strength limit r = fmin limit (fmax (strength *. r) (-.limit))

(* ---------------------------------------------------------------------------------------------- *)
(* The "SOR" option of the 2-D curves (POV-Ray's ROT2D macro): when the switch parameter (at
   [i]) is positive the curve in the x-y plane is turned into a surface of revolution about y,
   its x becoming the distance from the y axis less an offset (at [i+1]), and the plane then
   rotated by an angle in degrees (at [i+2]). [sor_x] and [sor_y] give the x and y the curve is
   evaluated at; both work out the same radius. *)

let deg_to_rad = 0.01745329251994329576

let[@inline] sor_on a i = a.(i) > 0.
let[@inline] sor_radius a i = sqrt ((a.(0) *. a.(0)) +. (a.(2) *. a.(2))) -. a.(i + 1)

let sor_x a i =
  if sor_on a i then begin
    let r = sor_radius a i and th = a.(i + 2) *. deg_to_rad in
    if th <> 0. then (r *. cos th) -. (a.(1) *. sin th) else r
  end
  else a.(0)

let sor_y a i =
  if sor_on a i then begin
    let th = a.(i + 2) *. deg_to_rad in
    if th <> 0. then (sor_radius a i *. sin th) +. (a.(1) *. cos th) else a.(1)
  end
  else a.(1)

(* ---------------------------------------------------------------------------------------------- *)
(* The algebraic cylinders: 2-D curves extruded along z (or revolved), clipped to ± a limit *)

let algbr_cyl1 a =
  let x = sor_x a 5 and y = sor_y a 5 in
  let x2 = x *. x and y2 = y *. y in
  let x = Float.abs x in
  let r = -.(((x2 *. x) -. x2) +. y2) in
  -.clip a.(3) a.(4) r

let algbr_cyl2 a =
  let x = sor_x a 5 and y = sor_y a 5 in
  let x2 = x *. x and y2 = y *. y in
  let r = -.(((((2. *. x2) *. x2) -. ((3. *. x2) *. y)) +. y2 -. ((2. *. y2) *. y)) +. (y2 *. y2)) in
  clip a.(3) a.(4) r

let algbr_cyl3 a =
  let x = sor_x a 5 and y = sor_y a 5 in
  let x2 = x *. x and y2 = y *. y in
  let r = -.((((x2 *. x2) +. (x2 *. y2)) -. ((2. *. x2) *. y) -. (x *. y2)) +. y2) in
  clip a.(3) a.(4) r

let algbr_cyl4 a =
  let x = sor_x a 5 and y = sor_y a 5 in
  let x2 = x *. x and y2 = y *. y in
  let r = -.((((x2 *. x2) +. (y2 *. y2)) +. ((2. *. x2) *. y2) +. ((3. *. x2) *. y)) -. (y2 *. y)) in
  clip a.(3) a.(4) r

(* ---------------------------------------------------------------------------------------------- *)
(* Surfaces in x, y, z *)

let bicorn a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  let s = a.(4) *. a.(4) in
  let r2 = (x2 +. z2 +. ((2. *. a.(4)) *. a.(1))) -. s in
  clip10 a.(3) ((y2 *. (s -. (x2 +. z2))) -. (r2 *. r2))

let bifolia a =
  let x2 = a.(0) *. a.(0) and z2 = a.(2) *. a.(2) in
  let r = x2 +. (a.(1) *. a.(1)) +. z2 in
  clip10 a.(3) (-.((r *. r) -. ((a.(4) *. (x2 +. z2)) *. a.(1))))

let sqrt2 = sqrt 2.0

let boy_surface a =
  let x = a.(0) and y = a.(1) and z = a.(2) in
  let x2 = x *. x and y2 = y *. y and z2 = z *. z in
  let r2 = 1. -. z and ph = x2 +. y2 in
  let t1 = (64. *. r2 *. r2 *. r2 *. z2) *. z in
  let t2 = (48. *. r2 *. r2 *. z2) *. ((3. *. x2) +. (3. *. y2) +. (2. *. z2)) in
  let t3 =
    (12. *. r2 *. z)
    *. (((27. *. ph *. ph) -. (24. *. z2 *. ph)) +. (36. *. sqrt2 *. y *. z *. (y2 -. (3. *. x2))) +. (4. *. z2 *. z2))
  in
  let t4 =
    ((9. *. x2) +. (9. *. y2) -. (2. *. z2))
    *. (((-81.) *. ph *. ph) -. (72. *. z2 *. ph) +. (108. *. sqrt2 *. x *. z *. (x2 -. (3. *. y2))) +. (4. *. z2 *. z2))
  in
  clip10 a.(3) (a.(4) *. (t1 -. t2 +. t3 +. t4))

let crossed_trough a = clip10 a.(3) ((a.(0) *. a.(0) *. a.(2) *. a.(2)) -. a.(1))

let cubic_saddle a = clip10 a.(3) (-.((a.(0) *. a.(0) *. a.(0)) -. (a.(1) *. a.(1) *. a.(1)) -. a.(2)))

(* f_cushion and f_odd: the same polynomial, with one product written in two orders *)
let cushion_odd ~odd a =
  let z = a.(2) in
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = z *. z in
  let xy = if odd then 2. *. y2 *. x2 else 2. *. x2 *. y2 in
  let r =
    (z2 *. x2) -. (z2 *. z2) -. (2. *. z *. x2) +. (2. *. z2 *. z) +. x2 -. z2
    -. ((x2 -. z) *. (x2 -. z))
    -. (y2 *. y2) -. xy -. (y2 *. z2) +. (2. *. y2 *. z) +. y2
  in
  clip10 a.(3) r

let devils_curve a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  clip10 a.(3) (-.((x2 *. x2) +. (2. *. x2 *. z2) -. (0.36 *. x2) -. (y2 *. y2) +. (0.25 *. y2) +. (z2 *. z2)))

let devils_curve_2d a =
  let x = sor_x a 6 and y = sor_y a 6 in
  let x2 = x *. x and y2 = y *. y in
  clip10 a.(3) (-.((x2 *. (x2 -. (a.(4) *. a.(4)))) -. (y2 *. (y2 -. (a.(5) *. a.(5))))))

let dupin_cyclid a =
  let x = a.(0) and y = a.(1) in
  let x2 = x *. x and y2 = y *. y and z2 = a.(2) *. a.(2) in
  let major = a.(4) and minor = a.(5) and dx = a.(6) and dy = a.(7) and inv = a.(8) in
  let r2 = inv *. inv and ph = minor *. minor and th = dy *. dy in
  let p1 = ph -. th -. ((dx +. major) *. (dx +. major)) in
  let p2 = ph -. th -. ((dx -. major) *. (dx -. major)) in
  let p3 = dx *. dx and p4 = major *. major in
  let t1 = p1 *. p2 *. ((x2 *. x2) +. (y2 *. y2) +. (z2 *. z2)) in
  let t2 = 2. *. (p1 *. p2 *. ((x2 *. y2) +. (x2 *. z2) +. (y2 *. z2))) in
  let t3 =
    2. *. r2
    *. (((-.th -. p3 +. ph +. p4) *. ((2. *. x *. dx) +. (2. *. y *. dy) -. r2)) -. (4. *. dy *. ph *. y))
    *. (x2 +. y2 +. z2)
  in
  let t4 = 4. *. r2 *. r2 *. ((dx *. x) +. (dy *. y)) *. (-.r2 +. (dy *. y) +. (dx *. x)) in
  let t5 = 4. *. r2 *. r2 *. p4 *. y2 in
  clip10 a.(3) (-.(t1 +. t2 +. t3 +. t4 +. t5 +. (r2 *. r2 *. r2 *. r2)))

(* POV-Ray writes 2/3, 1/4, 8/9 and 2/9 here, which C computes in integers: all four are 0 *)
let enneper a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  let z = if Float.abs a.(2) < 0.2 then 0.2 else a.(2) in
  let r = ((y2 -. x2) /. (2. *. z)) +. (2. *. z2 /. 9.) +. 0. in
  let r2 = ((y2 -. x2) /. (4. *. z)) -. (0. *. (x2 +. y2 +. (0. *. z2))) +. 0. in
  clip10 a.(3) (-.((r *. r *. r) -. (6. *. r2 *. r2)))

let folium_surface a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  clip10 a.(3) (((y2 +. z2) *. (1. +. ((a.(5) -. (4. *. a.(4))) *. a.(0)))) +. (x2 *. (1. +. a.(5))))

let folium_surface_2d a =
  let x = sor_x a 6 and y = sor_y a 6 in
  let x2 = x *. x and y2 = y *. y in
  clip10 a.(3) (-.((y2 *. (1. +. ((a.(5) -. (4. *. a.(4))) *. x))) +. (x2 *. (1. +. a.(5)))))

let glob a =
  let x = a.(0) in
  let x2 = x *. x in
  clip10 a.(3) ((0.5 *. x2 *. x2 *. x) +. (0.5 *. x2 *. x2) -. ((a.(1) *. a.(1)) +. (a.(2) *. a.(2))))

let heart a =
  let z = a.(2) in
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = z *. z in
  let s = (2. *. x2) +. y2 +. z2 -. 1. in
  clip10 a.(3) (-.((s *. s *. s) -. (0.1 *. x2 *. z2 *. z) -. (y2 *. z2 *. z)))

let hunt_surface a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  let s = x2 +. y2 +. z2 -. 13. and t = (3. *. x2) +. y2 -. (4. *. z2) -. 12. in
  clip10 a.(3) (-.((4. *. s *. s *. s) +. (27. *. t *. t)))

let hyperbolic_torus a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  let ph = a.(4) *. a.(4) and th = a.(5) *. a.(5) in
  let r =
    (x2 *. x2) +. (2. *. x2 *. y2) -. (2. *. x2 *. z2) -. (2. *. (ph +. th) *. x2) +. (y2 *. y2) -. (2. *. y2 *. z2)
    +. (2. *. (ph -. th) *. y2) +. (z2 *. z2) +. (2. *. (ph +. th) *. z2) +. ((ph -. th) *. (ph -. th))
  in
  clip10 a.(3) (-.r)

let kampyle_of_eudoxus a =
  let x2 = a.(0) *. a.(0) and dimple = a.(4) and close = a.(5) in
  let r =
    ((a.(1) *. a.(1)) +. (a.(2) *. a.(2))) -. (close *. close *. x2 *. x2) +. (close *. close *. dimple *. dimple *. x2)
  in
  clip10 a.(3) (-.r)

(* POV-Ray multiplies by the dimple once and the closeness three times here, unlike the 3-D form *)
let kampyle_of_eudoxus_2d a =
  let x = sor_x a 6 and y = sor_y a 6 in
  let x2 = x *. x and y2 = y *. y and dimple = a.(4) and close = a.(5) in
  clip10 a.(3) (-.(y2 -. (close *. close *. x2 *. x2) +. (close *. close *. dimple *. close *. x2)))

let klein_bottle a =
  let x = a.(0) and y = a.(1) and z = a.(2) in
  let x2 = x *. x and y2 = y *. y and z2 = z *. z in
  let plus = x2 +. y2 +. z2 +. (2. *. y) -. 1. and minus = x2 +. y2 +. z2 -. (2. *. y) -. 1. in
  clip10 a.(3) (-.((plus *. ((minus *. minus) -. (8. *. z2))) +. (16. *. x *. z *. minus)))

let kummer_surface_v1 a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  let r = (x2 *. x2) +. (y2 *. y2) +. (z2 *. z2) -. x2 -. y2 -. z2 -. (x2 *. y2) -. (x2 *. z2) -. (y2 *. z2) +. 1. in
  clip10 a.(3) (-.r)

let kummer_surface_v2 a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  let r =
    (x2 *. x2) +. (y2 *. y2) +. (z2 *. z2)
    +. (a.(4) *. (x2 +. y2 +. z2))
    +. (a.(5) *. ((x2 *. y2) +. (x2 *. z2) +. (y2 *. z2)))
    +. (a.(6) *. a.(0) *. a.(1) *. a.(2))
    -. 1.
  in
  clip10 a.(3) (-.r)

let lemniscate_of_gerono a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  clip10 a.(3) (-.((x2 *. x2) -. x2 +. y2 +. z2))

let lemniscate_of_gerono_2d a =
  let x = sor_x a 6 and y = sor_y a 6 in
  let x2 = x *. x and y2 = y *. y and size = a.(4) and width = a.(5) in
  clip10 a.(3) (-.(y2 -. (width *. width *. size *. size *. x2) +. (width *. width *. x2 *. x2)))

let mitre a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  clip10 a.(3) (-.((4. *. x2 *. (x2 +. y2 +. z2)) -. (y2 *. (1. -. y2 -. z2))))

let nodal_cubic a =
  let y = a.(1) and z = a.(2) in
  clip10 a.(3) (-.((y *. y *. y) +. (z *. z *. z) -. (6. *. y *. z)))

let ovals_of_cassini a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  let major = a.(4) in
  let r2 = x2 +. y2 +. z2 +. (major *. major) in
  clip10 a.(3) (-.((r2 *. r2) -. (a.(6) *. major *. major *. (x2 +. z2)) -. (a.(5) *. a.(5))))

let paraboloid a = clip10 a.(3) (-.((a.(0) *. a.(0)) -. a.(1) +. (a.(2) *. a.(2))))

let parabolic_torus a =
  let z = a.(2) in
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = z *. z in
  let ph = a.(4) *. a.(4) and th = a.(5) *. a.(5) in
  let r =
    (x2 *. x2) +. (2. *. x2 *. y2) -. (2. *. x2 *. z) -. ((ph +. th) *. x2) +. (y2 *. y2) -. (2. *. y2 *. z)
    +. ((ph -. th) *. y2) +. z2 +. ((ph +. th) *. z) +. ((ph -. th) *. (ph -. th))
  in
  clip10 a.(3) (-.r)

let pillow a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  clip10 a.(3) ((x2 *. x2) +. (y2 *. y2) +. (z2 *. z2) -. (x2 +. y2 +. z2))

let piriform a =
  let x = a.(0) in
  let x2 = x *. x in
  -.clip10 a.(3) (-.((x2 *. x2) -. (x2 *. x) +. (a.(1) *. a.(1)) +. (a.(2) *. a.(2))))

let piriform_2d a =
  let x = sor_x a 7 and y = sor_y a 7 in
  let x2 = x *. x and fat = a.(6) in
  clip10 a.(3) (-.((y *. y) -. (a.(4) *. fat *. fat *. x2 *. x) -. (a.(5) *. fat *. fat *. x2 *. x2)))

let quartic_paraboloid a =
  let x2 = a.(0) *. a.(0) and z2 = a.(2) *. a.(2) in
  clip10 a.(3) (-.((x2 *. x2) +. (z2 *. z2) -. a.(1)))

let quartic_saddle a =
  let x2 = a.(0) *. a.(0) and z2 = a.(2) *. a.(2) in
  clip10 a.(3) (-.((x2 *. x2) -. (z2 *. z2) -. a.(1)))

let quartic_cylinder a =
  let y = a.(1) in
  let x2 = a.(0) *. a.(0) and z2 = a.(2) *. a.(2) and d = a.(4) and w = a.(5) in
  clip10 a.(3) (-.(((x2 +. z2) *. y *. y) +. (w *. w *. (x2 +. z2)) -. (w *. w *. d *. d)))

let steiners_roman a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  clip10 a.(3) (-.((x2 *. y2) +. (x2 *. z2) +. (y2 *. z2) +. (a.(0) *. a.(1) *. a.(2))))

let strophoid a =
  let x = a.(0) in
  let x2 = x *. x and r2 = a.(6) *. a.(6) in
  let r = ((a.(5) -. x) *. ((a.(1) *. a.(1)) +. (a.(2) *. a.(2)))) -. (r2 *. a.(4) *. x2) -. (r2 *. x2 *. x) in
  clip10 a.(3) (-.r)

let strophoid_2d a =
  let x = sor_x a 7 and y = sor_y a 7 in
  let x2 = x *. x and y2 = y *. y and r2 = a.(6) *. a.(6) in
  clip10 a.(3) (-.(((a.(5) -. x) *. y2) -. (r2 *. a.(4) *. x2) -. (r2 *. x2 *. x)))

let torus2 a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  let ph = a.(4) *. a.(4) and th = a.(5) *. a.(5) in
  let r =
    (x2 *. x2) +. (y2 *. y2) +. (z2 *. z2) +. (2. *. x2 *. y2) +. (2. *. x2 *. z2) +. (2. *. y2 *. z2)
    -. (2. *. (ph +. th) *. x2) +. (2. *. (ph -. th) *. y2) -. (2. *. (ph +. th) *. z2) +. ((ph -. th) *. (ph -. th))
  in
  clip10 a.(3) (-.r)

let torus_gumdrop a =
  let x2 = a.(0) *. a.(0) and y2 = a.(1) *. a.(1) and z2 = a.(2) *. a.(2) in
  let r =
    (4. *. ((x2 *. x2) +. ((y2 +. z2) *. (y2 +. z2)))) +. (17. *. x2 *. (y2 +. z2)) -. (20. *. (x2 +. y2 +. z2)) +. 17.
  in
  clip10 a.(3) (-.r)

let umbrella a = clip10 a.(3) (-.((a.(0) *. a.(0)) -. (a.(1) *. a.(2) *. a.(2))))

let witch_of_agnesi a =
  let y = a.(1) in
  clip10 a.(3) (-.((a.(4) *. (y -. 1.)) +. (((a.(0) *. a.(0)) +. (a.(2) *. a.(2))) *. y)))

let witch_of_agnesi_2d a =
  let x = sor_x a 6 and y = sor_y a 6 in
  let x2 = x *. x in
  clip10 a.(3) (-.((a.(4) *. a.(4) *. y) +. (x2 *. y) -. a.(5)))

(* ---------------------------------------------------------------------------------------------- *)

let find k =
  match k with
  | 0 -> Some algbr_cyl1
  | 1 -> Some algbr_cyl2
  | 2 -> Some algbr_cyl3
  | 3 -> Some algbr_cyl4
  | 4 -> Some bicorn
  | 5 -> Some bifolia
  | 8 -> Some boy_surface
  | 11 -> Some crossed_trough
  | 12 -> Some cubic_saddle
  | 13 -> Some (cushion_odd ~odd:false)
  | 14 -> Some devils_curve
  | 15 -> Some devils_curve_2d
  | 16 -> Some dupin_cyclid
  | 18 -> Some enneper
  | 20 -> Some folium_surface
  | 21 -> Some folium_surface_2d
  | 22 -> Some glob
  | 23 -> Some heart
  | 30 -> Some hunt_surface
  | 31 -> Some hyperbolic_torus
  | 33 -> Some kampyle_of_eudoxus
  | 34 -> Some kampyle_of_eudoxus_2d
  | 35 -> Some klein_bottle
  | 36 -> Some kummer_surface_v1
  | 37 -> Some kummer_surface_v2
  | 38 -> Some lemniscate_of_gerono
  | 39 -> Some lemniscate_of_gerono_2d
  | 41 -> Some mitre
  | 42 -> Some nodal_cubic
  | 43 -> Some (cushion_odd ~odd:true)
  | 44 -> Some ovals_of_cassini
  | 45 -> Some paraboloid
  | 46 -> Some parabolic_torus
  | 48 -> Some pillow
  | 49 -> Some piriform
  | 50 -> Some piriform_2d
  | 54 -> Some quartic_paraboloid
  | 55 -> Some quartic_saddle
  | 56 -> Some quartic_cylinder
  | 65 -> Some steiners_roman
  | 66 -> Some strophoid
  | 67 -> Some strophoid_2d
  | 71 -> Some torus2
  | 72 -> Some torus_gumdrop
  | 73 -> Some umbrella
  | 74 -> Some witch_of_agnesi
  | 75 -> Some witch_of_agnesi_2d
  | _ -> None
