(* Tilings 1…27 of the XZ plane (J. Grimbert's, pattern.cpp tiling_pattern): with one kind of
   tile the value is 1 on its edge and falls to 0 inside; with several kinds each has its own
   band of values. Each folds the point into a fundamental cell by translations and mirrors. *)

open C_float

(* a point of the XZ plane taken through a substitution: an all-float record, so that its fields
   are stored unboxed *)
type point2 = { mutable px : float; mutable pz : float }

let sin18 = 0.30901699437494742410229341718282
let sin36 = 0.58778525229247312916870595463907
let sin54 = 0.80901699437494742410229341718282
let sin72 = 0.95105651629515357211643933337938
let sin108 = sin72
let sin144 = sin36
let sin162 = sin18
let cos18 = sin72
let cos36 = sin54
let cos72 = sin18
let cos108 = -.cos72
let cos144 = -.cos36
let cos162 = -.cos18
let tan18 = 0.32491969623290632615587141221513
let tan36 = 0.72654252800536088589546675748062
let tan54 = 1.3763819204711735382072095819109
let tan72 = 3.0776835371752534025702905760369
let tan126 = -.tan54
let tan144 = -.tan36
let tan162 = -.tan18
let phi = 1.6180339887498948482045868343656
let invphi = 0.61803398874989484820458683436564
let sqrphi = 2.6180339887498948482045868343656
let invsqrphi = 0.38196601125010515179541316563436
let tiling_epsilon = 1e-6

let square (p : Vec.t) =
  let x = Float.abs p.x in
  let x = x -. floor x in
  let x = 2. *. Float.abs (x -. 0.5) in
  let z = Float.abs p.z in
  let z = z -. floor z in
  let z = 2. *. Float.abs (z -. 0.5) in
  fmax x z

let hexagon (p : Vec.t) =
  let x = ref (p.x +. 0.5) and z = ref p.z in
  x := !x -. (3.0 *. floor (!x /. 3.0));
  z := !z -. (sqrt3 *. floor (!z /. sqrt3));
  (* [0,3) × [0,√3): fold the upper half, then the right half, onto [0,1.5] × [0,√3/2] *)
  if !z > sqrt3_2 then z := sqrt3 -. !z;
  if !x > 1.5 then begin
    x := !x -. 1.5;
    z := sqrt3_2 -. !z
  end;
  (* the lower left corner belongs to another hexagon *)
  if (sqrt3 *. !x) +. !z < sqrt3_2 then begin
    x := 0.5 -. !x;
    z := sqrt3_2 -. !z
  end;
  if !x > 1.0 then x := 2.0 -. !x;
  let dist1 = 1.0 -. (!z /. sqrt3_2) in
  let dist2 = 1.0 -. (((sqrt3 *. !x) +. !z -. sqrt3_2) /. sqrt3) in
  fmax 0.0 (fmin 1.0 (fmax dist1 dist2))

let triangle (p : Vec.t) =
  let x = ref p.x and z = ref p.z and delta = ref 0 in
  x := !x -. floor !x;
  z := !z -. (sqrt3 *. floor (!z /. sqrt3));
  if !z > sqrt3_2 then begin
    z := sqrt3 -. !z;
    delta := 1 - !delta
  end;
  if !x > 0.5 then x := 1.0 -. !x;
  if !x <> 0.0 then begin
    if !z /. !x > sqrt3 then begin
      z := sqrt3_2 -. !z;
      x := 0.5 -. !x;
      delta := 1 - !delta
    end
  end
  else begin
    z := sqrt3_2 -. !z;
    x := 0.5
  end;
  let dist1 = 1.0 -. (!z *. 2. *. sqrt3) in
  let dist2 = 1.0 -. (((sqrt3 *. !x) -. !z) *. sqrt3) in
  (float_of_int !delta /. 2.0) +. (0.5 *. fmax dist1 dist2)

(* the lozenge of tilings 4 and 5 in its cell [0,0.75] × [0,√3/4] *)
let[@inline] lozenge_cell x z =
  let x = ref x and z = ref z in
  if 2.0 *. !z > sqrt3_2 then begin
    z := sqrt3_2 -. !z;
    x := 1.5 -. !x
  end;
  if !x > 0.75 then x := !x -. 1.0;
  if !x <> 0.0 then
    if !z /. !x > sqrt3 then begin
      z := sqrt3_2 -. !z;
      x := 0.5 -. !x
    end;
  let dist1 = 1.0 -. (!z *. 4.0 *. sqrt3 /. 3.0) in
  let dist2 = 1.0 -. (Float.abs ((sqrt3 *. !x) -. !z) *. sqrt3 *. 2.0 /. 3.0) in
  fmax dist1 dist2

let lozenge (p : Vec.t) =
  let x = ref p.x and z = ref p.z in
  x := !x -. floor !x;
  z := !z -. (sqrt3 *. floor (!z /. sqrt3));
  if !z > sqrt3_2 then begin
    z := !z -. sqrt3_2;
    x := !x +. 0.5
  end;
  lozenge_cell !x !z

let rhombus (p : Vec.t) =
  let x = ref (p.x +. 0.5) and z = ref p.z and delta = ref 0 in
  x := !x -. (3.0 *. floor (!x /. 3.0));
  z := !z -. (sqrt3 *. floor (!z /. sqrt3));
  if !z > sqrt3_2 then begin
    z := sqrt3 -. !z;
    delta := 2 - !delta
  end;
  if !x > 1.5 then begin
    x := !x -. 1.5;
    z := sqrt3_2 -. !z;
    delta := 2 - !delta
  end;
  (* [0,1.5] × [0,√3/2]: part of a horizontal rhombus, half a vertical one, part of another *)
  if !x < 0.5 then begin
    x := 1.0 -. !x;
    delta := 2 - !delta
  end;
  x := !x -. 0.5;
  (* the vertical rhombus is turned onto the horizontal one on its right *)
  if !x = 0.0 || !z /. !x > sqrt3 then begin
    let dist1 = (!x /. 2.0) +. (!z *. sqrt3_2) and dist2 = (!z /. 2.0) -. (!x *. sqrt3_2) in
    z := dist2;
    x := dist1;
    delta := 1
  end;
  let answer = lozenge_cell !x !z /. 3.0 in
  let answer = answer +. (float_of_int !delta /. 3.0) in
  fmax 0.0 (fmin 1.0 answer)

let rectangle (p : Vec.t) =
  let x = ref (p.x -. (4.0 *. floor (p.x /. 4.0))) and z = ref (p.z -. (4.0 *. floor (p.z /. 4.0))) in
  let delta = ref 1.0 in
  (match c_int !x + (c_int !z * 4) with
  | 0 | 4 -> z := !z -. 1.0
  | 1 | 2 ->
      x := !x -. 2.0;
      delta := 0.0
  | 3 -> x := !x -. 3.0
  | 5 | 9 ->
      x := !x -. 1.0;
      z := !z -. 2.0
  | 6 | 7 ->
      x := !x -. 3.0;
      z := !z -. 1.0;
      delta := 0.0
  | 8 ->
      z := !z -. 2.0;
      delta := 0.0
  | 10 | 14 ->
      x := !x -. 2.0;
      z := !z -. 3.0
  | 11 ->
      x := !x -. 4.0;
      z := !z -. 2.0;
      delta := 0.0
  | 12 | 13 ->
      x := !x -. 1.0;
      z := !z -. 3.0;
      delta := 0.0
  | 15 ->
      x := !x -. 3.0;
      z := !z -. 4.0
  | _ -> ());
  let x, z =
    if !delta = 1.0 then (2. *. Float.abs (!x -. 0.5), 2. *. (fmax (Float.abs !z) 0.5 -. 0.5))
    else (2. *. (fmax (Float.abs !x) 0.5 -. 0.5), 2. *. Float.abs (!z -. 0.5))
  in
  Float.abs ((fmax x z /. 2.0) +. (!delta /. 2.))

let octa_square (p : Vec.t) =
  let period = sqrt2 +. 1.0 in
  let z = p.z -. (period *. floor (p.z /. period)) in
  let z = Float.abs (z -. (sqrt2_2 +. 0.5)) in
  let x = p.x -. (period *. floor (p.x /. period)) in
  let x = Float.abs (x -. (sqrt2_2 +. 0.5)) in
  let x, z = if z > x then (z, x) else (x, z) in
  if x +. z < sqrt2_2 then (x +. z) /. sqrt2
  else
    let dist1 = 1.0 -. z and dist2 = (sqrt2 +. sqrt2_2 -. (x +. z)) /. sqrt2 in
    fmax 0.500000000001 (fmax dist1 dist2)

let square_triangle (p : Vec.t) =
  let x = ref p.x and z = ref p.z and delta = ref 0 in
  x := !x -. floor !x;
  z := !z -. ((2.0 +. sqrt3) *. floor (!z /. (sqrt3 +. 2.0)));
  if !z > sqrt3_2 +. 1.0 then begin
    z := !z -. (sqrt3_2 +. 1.0);
    x := !x +. if !x > 0.5 then -0.5 else 0.5
  end;
  if !x > 0.5 then x := 1.0 -. !x;
  z := !z -. 1.0;
  if !z > 0.0 then begin
    (* a triangle *)
    if !x <> 0.0 then begin
      if !z /. !x > sqrt3 then begin
        z := sqrt3_2 -. !z;
        x := 0.5 -. !x;
        delta := 1 - !delta
      end
    end
    else begin
      z := sqrt3_2 -. !z;
      x := 0.5;
      delta := 1 - !delta
    end;
    let dist1 = 1.0 -. (2. *. !z *. sqrt3) and dist2 = 1.0 -. (((sqrt3 *. !x) -. !z) *. sqrt3) in
    (float_of_int !delta +. fmax dist1 dist2) /. 3.0
  end
  else begin
    (* a square *)
    if !z < -0.5 then z := -1.0 -. !z;
    if !x > 0.5 then x := 1.0 -. !x;
    let dist1 = fmin (2. +. (2. *. sqrt3 *. Float.abs !x)) 3.0 in
    let dist2 = fmin (2. +. (2. *. sqrt3 *. Float.abs !z)) 3.0 in
    (5.0000001 -. fmin dist1 dist2) /. 3.0
  end

let hexa_triangle (p : Vec.t) =
  let x = ref (p.x +. 0.5) and z = ref p.z and delta = ref 0 in
  x := !x -. (2.0 *. floor (!x /. 2.0));
  z := !z -. (2.0 *. sqrt3 *. floor (!z /. (sqrt3 *. 2.0)));
  if !z > sqrt3 then begin
    z := !z -. sqrt3;
    x := !x +. if !x < 1.0 then 1.0 else -1.0
  end;
  if !z > sqrt3_2 then begin
    z := sqrt3 -. !z;
    delta := 1 - !delta
  end;
  if !x > 1.0 then x := 2.0 -. !x;
  (* [0,1] × [0,√3/2]: a triangle in the lower left corner, the hexagon's centre upper right *)
  if (sqrt3 *. !x) +. !z < sqrt3_2 then
    let dist1 = 1.0 -. (!z *. 2. *. sqrt3) in
    let dist2 = 1.0 +. (((sqrt3 *. !x) +. !z -. sqrt3_2) *. sqrt3) in
    (float_of_int !delta +. fmax dist1 dist2) /. 3.0
  else
    let dist1 = 2. +. (2. *. (!z *. sqrt3)) in
    let dist2 = 2. +. (2. *. ((sqrt3 *. !x) +. !z -. sqrt3_2) *. sqrt3_2) in
    fmax (5.0 -. fmin dist1 dist2) 2.0000001 /. 3.0

let square_offset (p : Vec.t) =
  let z = p.z -. (2.0 *. floor (p.z /. 2.0)) in
  let x, z = if z > 1.0 then (p.x +. 0.5, z -. 1.0) else (p.x, z) in
  let x = x -. floor x in
  fmax (2. *. Float.abs (x -. 0.5)) (2. *. Float.abs (z -. 0.5))

(* a central square and four 2×1 rectangles around it, in the cell [0,3)²: tilings 11, 12 *)
let[@inline] square_rectangle_cell x z =
  let x = ref x and z = ref z and delta = ref 2.0 in
  (match c_int !x + (c_int !z * 3) with
  | 0 | 3 -> z := !z -. 1.0
  | 1 | 2 ->
      x := !x -. 2.0;
      delta := 1.0
  | 4 ->
      x := !x -. 1.0;
      z := !z -. 1.0;
      delta := 0.0
  | 5 | 8 ->
      x := !x -. 2.0;
      z := !z -. 2.0
  | 6 | 7 ->
      x := !x -. 1.0;
      z := !z -. 2.0;
      delta := 1.0
  | _ -> ());
  if !delta = 1.0 then begin
    x := Float.abs !x;
    x := 2.0 *. (fmax !x 0.5 -. 0.5);
    z := 2.0 *. Float.abs (!z -. 0.5)
  end;
  if !delta = 2.0 then begin
    x := 2.0 *. Float.abs (!x -. 0.5);
    z := Float.abs !z;
    z := 2.0 *. (fmax !z 0.5 -. 0.5)
  end;
  if !delta = 0.0 then begin
    x := 2.0 *. Float.abs (!x -. 0.5);
    z := 2.0 *. Float.abs (!z -. 0.5)
  end;
  (fmax !x !z +. !delta) /. 3.0

let square_rectangle (p : Vec.t) =
  square_rectangle_cell (p.x -. (3.0 *. floor (p.x /. 3.0))) (p.z -. (3.0 *. floor (p.z /. 3.0)))

(* the same cell mirrored four times in [0,6)², so the rectangles turn both ways *)
let rectangle_square (p : Vec.t) =
  let fold a = Float.abs (a -. (6.0 *. floor (a /. 6.0)) -. 3.0) in
  square_rectangle_cell (fold p.x) (fold p.z)

(* squares at 45°, folded into [0,2]² of √2-scaled space: tilings 13 and 14 *)
let[@inline] internal_fold a =
  let a = a *. sqrt2 in
  Float.abs (a -. (4.0 *. floor (a /. 4.0)) -. 2.0)

let square_internal (p : Vec.t) =
  let x = internal_fold p.x and z = internal_fold p.z in
  match c_int x + (c_int z * 2) with
  | 0 ->
      let x = fmax (x -. 0.5) 0.0 *. 2.0 and z = fmax (z -. 0.5) 0.0 *. 2.0 in
      fmax x z /. 3.0
  | 1 ->
      let answer = (2.0 +. (Float.abs (1.5 -. x) *. 2.0)) /. 3.0 in
      if z > 0.5 then fmax answer ((3.0 -. (sqrt2 *. Float.abs (x -. z))) /. 3.0) else answer
  | 2 ->
      let answer = (1.0 +. (Float.abs (1.5 -. z) *. 2.0)) /. 3.0 in
      if x > 0.5 then fmax answer ((2.0 -. (sqrt2 *. Float.abs (x -. z))) /. 3.0) else answer
  | 3 ->
      if x > z then
        fmax ((2.0 +. (Float.abs (1.5 -. x) *. 2.0)) /. 3.0) ((3.0 -. (sqrt2 *. Float.abs (z -. x))) /. 3.0)
      else fmax ((1.0 +. (Float.abs (1.5 -. z) *. 2.0)) /. 3.0) ((2.0 -. (sqrt2 *. Float.abs (x -. z))) /. 3.0)
  | _ -> 0.

let square_internal_5 (p : Vec.t) =
  let x = p.x *. sqrt2 in
  let x = x -. (4.0 *. floor (x /. 4.0)) -. 2.0 in
  let mir_x = if x < 0. then 1. else 0. in
  let x = Float.abs x in
  let z = p.z *. sqrt2 in
  let z = z -. (4.0 *. floor (z /. 4.0)) -. 2.0 in
  let mir_z = if z < 0. then 2. else 3. in
  let z = Float.abs z in
  match c_int x + (c_int z * 2) with
  | 0 ->
      let x = fmax (x -. 0.5) 0.0 *. 2.0 and z = fmax (z -. 0.5) 0.0 *. 2.0 in
      (4.000001 +. fmax x z) /. 5.0
  | 1 ->
      let answer = Float.abs (1.5 -. x) *. 2.0 in
      let answer = if z > 0.5 then fmax answer (1.0 -. (sqrt2 *. Float.abs (x -. z))) else answer in
      (answer +. mir_x) /. 5.0
  | 2 ->
      let answer = Float.abs (1.5 -. z) *. 2.0 in
      let answer = if x > 0.5 then fmax answer (1.0 -. (sqrt2 *. Float.abs (x -. z))) else answer in
      (answer +. mir_z) /. 5.0
  | 3 ->
      if x > z then (fmax (Float.abs (1.5 -. x) *. 2.0) (1.0 -. (sqrt2 *. Float.abs (z -. x))) +. mir_x) /. 5.0
      else (fmax (Float.abs (1.5 -. z) *. 2.0) (1.0 -. (sqrt2 *. Float.abs (x -. z))) +. mir_z) /. 5.0
  | _ -> 0.

let square_double (p : Vec.t) =
  let x = ref (p.x -. (5.0 *. floor (p.x /. 5.0))) and z = ref (p.z -. (5.0 *. floor (p.z /. 5.0))) in
  let delta = ref 0.50000001 in
  (* the corner of the cell's tile, and whether it is a small square (delta 0) *)
  let dx, dz, small =
    match c_int !x + (c_int !z * 5) with
    | 0 -> (0.0, 0.0, true)
    | 1 | 2 -> (2.0, 0.0, false)
    | 3 | 4 | 8 | 9 -> (4.0, 1.0, false)
    | 5 | 6 | 10 | 11 -> (1.0, 2.0, false)
    | 7 -> (2.0, 1.0, true)
    | 12 | 13 | 17 | 18 -> (3.0, 3.0, false)
    | 14 -> (4.0, 2.0, true)
    | 15 | 20 -> (0.0, 4.0, false)
    | 16 -> (1.0, 3.0, true)
    | 21 | 22 -> (2.0, 5.0, false)
    | 23 -> (3.0, 4.0, true)
    | 24 | 19 -> (5.0, 4.0, false)
    | _ -> (0.0, 0.0, false)
  in
  x := !x -. dx;
  z := !z -. dz;
  if small then delta := 0.0;
  let x, z =
    if !delta <> 0. then (2. *. (fmax (Float.abs !x) 0.5 -. 0.5), 2. *. (fmax (Float.abs !z) 0.5 -. 0.5))
    else (2. *. Float.abs (!x -. 0.5), 2. *. Float.abs (!z -. 0.5))
  in
  Float.abs ((fmax x z /. 2.0) +. !delta)

(* one hexagon, squares and triangles in [0, 3+√3) × [0, 2(1+√3)), folded onto
   [0, 1+√3/2]²; [tiles] is 3 (hexagon, square, triangle) or 6 (the orientations apart) *)
let hexa_square_triangle_n six (p : Vec.t) =
  let x = ref (p.x +. 0.5) and z = ref p.z in
  let mir_x = ref 0 and mir_z = ref 0 and rota = ref 0 in
  x := !x -. ((3.0 +. sqrt3) *. floor (!x /. (3.0 +. sqrt3)));
  z := !z -. (2.0 *. (1.0 +. sqrt3) *. floor (!z /. ((sqrt3 +. 1.0) *. 2.0)));
  if !x > sqrt3_2 +. 1.5 then begin
    x := !x -. (sqrt3_2 +. 1.5);
    z := !z +. if !z < sqrt3 +. 1.0 then sqrt3_2 +. 0.5 else -1. *. (sqrt3_2 +. 0.5)
  end;
  if !z > sqrt3 +. 1.0 then z := !z -. (sqrt3 +. 1.0);
  if !z > 0.5 +. sqrt3_2 then begin
    z := sqrt3 +. 1.0 -. !z;
    mir_z := 1 - !mir_z
  end;
  if !x > 1.0 +. sqrt3_2 then begin
    x := sqrt3 +. 2.0 -. !x;
    mir_x := 1 - !mir_x
  end;
  (* a triangle or a square: turned by 60° about the hexagon's corner into the lower part *)
  if (sqrt3 *. !x) +. !z < sqrt3_2 +. 2.0 && !x < 0.5 +. sqrt3_2 then begin
    z := !z -. (0.5 +. sqrt3_2);
    x := !x -. (1.0 +. sqrt3_2);
    let dist1 = (!x /. 2.0) -. (!z *. sqrt3_2) and dist2 = (!z /. 2.0) +. (!x *. sqrt3_2) in
    z := dist2;
    x := dist1;
    z := !z +. (0.5 +. sqrt3_2);
    x := !x +. (1.0 +. sqrt3_2);
    rota := 1 - !rota;
    if !z < 0. then z := !z *. -1.;
    if !x > 1.0 +. sqrt3_2 then begin
      x := sqrt3 +. 2.0 -. !x;
      mir_x := 1 - !mir_x;
      mir_z := 1 - !mir_z
    end
  end;
  if (not ((sqrt3 *. !x) +. !z < sqrt3_2 +. 2.0)) && not (!z < 0.5) then begin
    (* the hexagon *)
    let z = Float.abs (!z -. 0.5) and x = Float.abs (!x -. sqrt3_2) in
    let dist1 = 2. *. z *. sqrt3 and dist2 = (((sqrt3 *. x) +. z) *. sqrt3) -. 1.5 in
    if six then fmax (6.0 -. fmin dist1 dist2) 5.000001 /. 6.0 else fmax (3.0 -. fmin dist1 dist2) 2.0000001 /. 3.0
  end
  else if !z < 0.5 then
    if !x > sqrt3_2 +. 0.5 then begin
      (* a square *)
      let x = !x -. (sqrt3_2 +. 0.5) and z = !z -. 0.5 in
      let dist1 = fmax (1.0 +. (z *. 2. *. sqrt3)) 0.0 and dist2 = fmax (1.0 -. (x *. 2. *. sqrt3)) 0.0 in
      if six then
        (fmax dist1 dist2 +. (float_of_int !rota *. (1.000001 +. float_of_int ((!mir_x + !mir_z) mod 2)))) /. 6.0
      else fmax dist1 dist2 /. 3.0
    end
    else begin
      (* a triangle *)
      let x = Float.abs (!x -. (sqrt3_2 +. 0.5)) in
      let dist2 = (((sqrt3 *. !z) +. x) *. sqrt3) +. 0.5 and dist1 = 2.0 -. (x *. 2.0 *. sqrt3) in
      if six then
        let answer = fmax dist1 dist2 in
        (if (!rota + !mir_x) mod 2 <> 0 then 2.0 +. answer else 3.0 +. answer) /. 6.0
      else fmax dist1 dist2 /. 3.0
    end
  else 0.

let rectangle_pair (p : Vec.t) =
  let x = ref (p.x -. (4.0 *. floor (p.x /. 4.0))) and z = ref (p.z -. (4.0 *. floor (p.z /. 4.0))) in
  let delta = ref 1.0 in
  (* the corner of the cell's rectangle, and whether it lies along x (delta 0) *)
  let dx, dz, along_x =
    match c_int !x + (c_int !z * 4) with
    | 0 | 4 -> (0.0, 1.0, false)
    | 1 | 5 -> (1.0, 1.0, false)
    | 2 | 3 -> (3.0, 0.0, true)
    | 6 | 7 -> (3.0, 1.0, true)
    | 8 | 9 -> (1.0, 2.0, true)
    | 12 | 13 -> (1.0, 3.0, true)
    | 10 | 14 -> (2.0, 3.0, false)
    | 11 | 15 -> (3.0, 3.0, false)
    | _ -> (0.0, 0.0, false)
  in
  x := !x -. dx;
  z := !z -. dz;
  if along_x then delta := 0.0;
  let x, z =
    if !delta = 1.0 then (2. *. Float.abs (!x -. 0.5), 2. *. (fmax (Float.abs !z) 0.5 -. 0.5))
    else (2. *. (fmax (Float.abs !x) 0.5 -. 0.5), 2. *. Float.abs (!z -. 0.5))
  in
  Float.abs ((fmax x z +. !delta) /. 2.0)

(* tilings 19 and 20: hexagons ringed by triangles, the rows shifted right or left; once the
   point is in the cell [0,7) × [0,3√3/2), the triangles and hexagons are found alike *)
let[@inline] hexa_tri_cell x z =
  let x = ref x and z = ref z and delta = ref 0 in
  let zzof = c_int (!z /. sqrt3_2) in
  let zzof =
    if zzof = 2 then begin
      z := (2. *. sqrt3) -. !z;
      delta := 1 - !delta;
      1
    end
    else zzof
  in
  if zzof = 0 || !x > 2.0 || !z +. (sqrt3 *. !x) < sqrt3 || (sqrt3 *. !x) -. !z > sqrt3 then begin
    (* a triangle *)
    x := !x -. (1.0 *. floor (!x /. 1.0));
    z := !z -. (sqrt3 *. floor (!z /. sqrt3));
    if !z > sqrt3_2 then begin
      z := sqrt3 -. !z;
      delta := 1 - !delta
    end;
    if !x > 0.5 then x := 1.0 -. !x;
    if !x <> 0.0 then begin
      if !z /. !x > sqrt3 then begin
        z := sqrt3_2 -. !z;
        x := 0.5 -. !x;
        delta := 1 - !delta
      end
    end
    else begin
      z := sqrt3_2 -. !z;
      x := 0.5;
      delta := 1 - !delta
    end;
    let dist1 = 1.0 -. (!z *. 2. *. sqrt3) and dist2 = 1.0 -. (((sqrt3 *. !x) -. !z) *. sqrt3) in
    (float_of_int !delta +. fmax dist1 dist2) /. 3.0
  end
  else begin
    (* a hexagon *)
    z := !z -. sqrt3_2;
    if !x > 1.0 then x := 2.0 -. !x;
    let dist1 = 2. +. (2. *. (!z *. sqrt3)) and dist2 = 2. +. (2. *. ((sqrt3 *. !x) +. !z -. sqrt3_2) *. sqrt3_2) in
    fmax (5.0 -. fmin dist1 dist2) 2.000001 /. 3.0
  end

(* the row of three half-heights the point is in, −1 below the axis; each shifts the rows by
   half a unit *)
let[@inline] hexa_tri_rows z =
  let zzof = c_int (z /. sqrt3_2) / 3 in
  if z < 0. then zzof - 1 else zzof

let hexa_tri_right (p : Vec.t) =
  let x = ref (p.x +. (float_of_int (hexa_tri_rows p.z) /. 2.0)) in
  let z = ref (p.z -. (3. *. sqrt3_2 *. floor (p.z /. (3. *. sqrt3_2)))) in
  x := !x +. 7.0;
  x := !x -. (7.0 *. floor (!x /. 7.0));
  if !x > 4.5 && !z > sqrt3 then begin
    x := !x -. 4.5;
    z := !z -. sqrt3_2
  end;
  if !x > 5.0 && !z < sqrt3_2 then begin
    x := !x -. 5.;
    z := !z +. sqrt3
  end;
  if !x > 2.5 && !z < sqrt3 then begin
    x := !x -. 2.5;
    z := !z +. sqrt3_2
  end;
  hexa_tri_cell !x !z

let hexa_tri_left (p : Vec.t) =
  let x = ref (p.x -. (float_of_int (hexa_tri_rows p.z) /. 2.0)) in
  let z = ref (p.z -. (3. *. sqrt3_2 *. floor (p.z /. (3. *. sqrt3_2)))) in
  x := !x +. 7.0;
  x := !x -. (7.0 *. floor (!x /. 7.0));
  if !x > 2.0 && !z < sqrt3_2 then begin
    x := !x -. 2.0;
    z := !z +. sqrt3
  end;
  if !x > 4.5 && !z < sqrt3 then begin
    x := !x -. 4.5;
    z := !z +. sqrt3_2
  end;
  if !x > 2.5 && !z > sqrt3 then begin
    x := !x -. 2.5;
    z := !z -. sqrt3_2
  end;
  hexa_tri_cell !x !z

let square_tri (p : Vec.t) =
  let period = 1.0 +. sqrt3 in
  let x = ref (p.x -. (period *. floor (p.x /. period))) and z = ref (p.z -. (period *. floor (p.z /. period))) in
  let delta = ref 0 and beta = ref 0 in
  if !z > 0.5 +. sqrt3_2 then begin
    z := 1.0 +. sqrt3 -. !z;
    delta := 1 - !delta
  end;
  if !x > 0.5 +. sqrt3_2 then begin
    x := 1.0 +. sqrt3 -. !x;
    delta := 1 - !delta;
    beta := 1
  end;
  (* [0, (1+√3)/2]²: still a mirror and a rotation *)
  let xflop = (2.0 *. !x) +. ((sqrt3 -. 1.0) *. 2.0 *. !z /. (sqrt3 +. 1.0)) > sqrt3 in
  let zflop = (2.0 *. !z *. sqrt3) +. ((sqrt3 -. 3.0) *. 2.0 *. !x /. (sqrt3 +. 1.0)) > sqrt3 in
  let delta = !delta and beta = !beta in
  let gamma =
    match (xflop, zflop) with
    | false, false -> 2 * beta
    | true, false ->
        let s = !x in
        x := !z;
        z := sqrt3_2 +. 0.5 -. s;
        if beta <> 0 then 1 + (2 * delta) else 3 - (2 * delta)
    | false, true ->
        let s = !z in
        z := !x;
        x := sqrt3_2 +. 0.5 -. s;
        if beta <> 0 then 3 - (2 * delta) else 1 + (2 * delta)
    | true, true ->
        x := sqrt3_2 +. 0.5 -. !x;
        z := sqrt3_2 +. 0.5 -. !z;
        if beta <> 0 then 0 else 2
  in
  if !x = 0.0 then begin
    z := 0.0;
    x := 0.0
  end;
  let slop1 = (!z *. 2. *. sqrt3) -. sqrt3 +. (!x *. 2.) in
  if slop1 < 0. then
    (* a triangle *)
    let dist1 = -1.5 /. sqrt3 *. slop1 and dist2 = 2.0 *. !x *. sqrt3 in
    (float_of_int gamma +. 1.0 -. fmin dist1 dist2) /. 6.0
  else
    (* a square *)
    let s = fmin (slop1 *. (1.5 /. sqrt3)) 1.0 in
    if delta <> 0 then fmin (fmax (((s *. -1.) +. 6.0) /. 6.0) (5.000001 /. 6.0)) 1.0
    else fmax (fmin (((s *. -1.) +. 5.0) /. 6.0) (5.0 /. 6.0)) (4.000001 /. 6.0)

let dodeca_tri (p : Vec.t) =
  let x = ref (p.x -. ((2.0 +. sqrt3) *. floor (p.x /. (2.0 +. sqrt3)))) in
  let z = ref (p.z -. ((3.0 +. (2.0 *. sqrt3)) *. floor (p.z /. (3.0 +. (2.0 *. sqrt3))))) in
  let toggle = ref 0 in
  if !z > sqrt3 +. 1.5 then begin
    z := !z -. (sqrt3 +. 1.5);
    x := !x +. ((if !x < 1.0 +. sqrt3_2 then 1.0 else -1.0) *. (1.0 +. sqrt3_2))
  end;
  if !x > 1.0 +. sqrt3_2 then x := 2.0 +. sqrt3 -. !x;
  if !z > 1.0 +. sqrt3_2 then begin
    z := 2.0 +. sqrt3 -. !z;
    toggle := 1 - !toggle
  end;
  let dist2 = ref (!x -. sqrt3_2 -. 0.5 +. (!z *. sqrt3)) in
  if !dist2 < 0.0 then begin
    let tmpx = !x and tmpz = !z in
    x := ((1.0 +. sqrt3) /. 4.0) +. (0.5 *. tmpx) -. (sqrt3_2 *. tmpz);
    z := ((3.0 +. sqrt3) /. 4.0) -. (sqrt3_2 *. tmpx) -. (0.5 *. tmpz);
    dist2 := !dist2 *. -1.0
  end;
  let dist1 = !z *. 3.0 in
  let dist3 = (!z -. sqrt3_2 -. 0.5 +. (!x *. sqrt3)) *. sqrt3 in
  let dist2 = !dist2 *. sqrt3 in
  let dist4 = !x *. 3.0 in
  if dist3 < 0.0 then (fmax dist3 (-1.0) +. float_of_int (1 + !toggle)) /. 3.0
  else
    (* the dodecagon *)
    let r = fmin (fmin (fmin (fmin dist1 dist2) dist3) dist4) 1.0 in
    (3.0000001 -. r) /. 3.0

(* dodecagons, hexagons and squares in [0, 3+√3) × [0, 3+3√3): tilings 23 and 24 *)
let dodeca_hex_n five (p : Vec.t) =
  let x = ref (p.x -. ((3.0 +. sqrt3) *. floor (p.x /. (3.0 +. sqrt3)))) in
  let z = ref (p.z -. ((3.0 +. (3.0 *. sqrt3)) *. floor (p.z /. (3.0 +. (3.0 *. sqrt3))))) in
  let mir_x = ref 0 and mir_z = ref 0 in
  if !z > (1.5 *. sqrt3) +. 1.5 then begin
    z := !z -. ((1.5 *. sqrt3) +. 1.5);
    x := !x +. ((if !x < 1.5 +. sqrt3_2 then 1.0 else -1.0) *. (1.5 +. sqrt3_2))
  end;
  if !x > 1.5 +. sqrt3_2 then begin
    x := 3.0 +. sqrt3 -. !x;
    mir_x := 1 - !mir_x
  end;
  if !z > 1.0 +. sqrt3 then begin
    z := 2.0 +. (2.0 *. sqrt3) -. !z;
    mir_z := 1 - !mir_z
  end;
  if !x -. sqrt3_2 -. 1.5 +. (!z *. sqrt3) < 0.0 then begin
    let tmpx = !x and tmpz = !z in
    x := ((3.0 +. sqrt3) /. 4.0) +. (0.5 *. tmpx) -. (sqrt3_2 *. tmpz);
    z := ((3.0 +. (3.0 *. sqrt3)) /. 4.0) -. (sqrt3_2 *. tmpx) -. (0.5 *. tmpz)
  end;
  let x = !x and z = !z in
  let dist2 = x -. sqrt3_2 -. 2.5 +. (z *. sqrt3) in
  let dist1 = (z *. 2.0) -. sqrt3 in
  let dist3 = z -. (1.5 *. sqrt3) -. 0.5 +. (x *. sqrt3) in
  let dist4 = (x -. 0.5) *. 2.0 in
  let r =
    if dist2 >= 0.0 && dist1 >= 0.0 && dist3 >= 0.0 && dist4 >= 0.0 then
      (* the dodecagon *)
      let r = fmin (fmin (fmin (fmin dist1 dist2) dist3) dist4) 1.0 in
      (if five then 5.000001 else 3.000001) -. r
    else
      let dist5 = (2. *. z) -. (2. *. sqrt3) -. 1.0 in
      if dist5 >= 0. then 2.0 -. fmin dist5 (dist4 *. -1.0)
      else
        let dist6 = (sqrt3 *. x) -. z -. sqrt3_2 +. 0.5 in
        let dist7 = dist6 -. 2.0 in
        match (if dist6 >= 0. then 0 else 1) + if dist7 >= 0.0 then 2 else 0 with
        | 1 ->
            (* the hexagon on the left *)
            1.0 -. fmin (fmin (fmin (dist6 *. -1.0) (dist3 *. -1.0)) (dist5 *. -1.0)) 1.0
        | 2 ->
            (* the hexagon below *)
            1.0 -. fmin (fmin dist7 (dist1 *. -1.0)) 1.0
        | _ ->
            (* the slanted square *)
            let r = fmin (fmin dist6 (dist2 *. -1.0)) (dist7 *. -1.0) in
            if five then float_of_int ((!mir_z + !mir_x) mod 2) +. 3.0 -. r else 2.0 -. r
  in
  r /. if five then 5.0 else 3.0

(* Penrose's P2 (kites and darts) and P3 (rhombs): the point, scaled up by φ each step, is
   taken down [depth] levels of the substitution of half-kites and half-darts; the tile it ends
   in gives the value *)
let penrose_halves x z depth rhombs =
  let x = ref x and z = ref z and depth = ref depth and kite = ref true and result = ref 0. and fin = ref false in
  while not !fin do
    let px = !x and pz = Float.abs !z in
    if !kite then
      if !depth > 0 then begin
        if pz < (px -. invphi) *. tan144 then begin
          x := px *. phi;
          z := pz *. phi;
          kite := false
        end
        else begin
          let x1 = px -. cos36 and z1 = pz -. sin36 in
          let rot_x = (x1 *. cos108) -. (z1 *. sin108) and rot_z = (z1 *. cos108) +. (x1 *. sin108) in
          x := rot_x *. phi;
          z := rot_z *. phi
        end;
        decr depth
      end
      else begin
        fin := true;
        result :=
          if rhombs then
            if pz < (px -. invphi) *. tan72 then
              let dist1 = Float.abs ((sin72 *. (px -. invphi)) -. (cos72 *. pz)) *. 5.55
              and dist2 = Float.abs ((sin108 *. (px -. 1.)) -. (cos108 *. pz)) *. 5.55 in
              max3 (1.0 -. (dist1 /. 2.)) (1.0 -. (dist2 /. 2.)) (0.5 +. tiling_epsilon)
            else
              let dist1 = Float.abs pz *. 5.55
              and dist2 = Float.abs ((sin72 *. (px -. invphi)) -. (cos72 *. pz)) *. 5.55 in
              fmin (max3 (0.5 -. (dist1 /. 2.)) (0.5 -. (dist2 /. 2.)) 0.0) (0.5 -. tiling_epsilon)
          else
            let dist1 = Float.abs ((sin36 *. px) -. (cos36 *. pz)) *. 4.46
            and dist2 = Float.abs ((sin108 *. (px -. 1.)) -. (cos108 *. pz)) *. 4.46 in
            fmin (max3 (0.5 -. (dist1 /. 2.)) (0.5 -. (dist2 /. 2.)) 0.0) (0.5 -. tiling_epsilon)
      end
    else if !depth > 0 then begin
      if pz < (px -. invphi) *. -.tan72 then begin
        let rot_x = (px *. cos36) +. (pz *. sin36) and rot_z = (pz *. cos36) -. (px *. sin36) in
        x := rot_x *. phi;
        z := rot_z *. phi;
        kite := true
      end
      else begin
        let x1 = px -. 1. in
        let rot_x = (x1 *. cos144) +. (pz *. sin144) and rot_z = (pz *. cos144) -. (x1 *. sin144) in
        x := rot_x *. phi;
        z := rot_z *. phi
      end;
      decr depth
    end
    else begin
      fin := true;
      result :=
        if rhombs then
          let dist1 = Float.abs ((sin36 *. px) -. (cos36 *. pz)) *. 5.55
          and dist2 = Float.abs ((sin144 *. (px -. 1.)) -. (cos144 *. pz)) *. 5.55 in
          fmin (max3 (0.5 -. (dist1 /. 2.)) (0.5 -. (dist2 /. 2.)) 0.0) (0.5 -. tiling_epsilon)
        else
          let dist1 = Float.abs pz *. 4.46 and dist2 = Float.abs ((sin144 *. (px -. 1.)) -. (cos144 *. pz)) *. 4.46 in
          max3 (1.0 -. (dist1 /. 2.)) (1.0 -. (dist2 /. 2.)) (0.5 +. tiling_epsilon)
    end
  done;
  !result

(* the five-fold symmetry: z made positive, and a point outside the wedge of ±36° about +x
   turned into it; [r] is the point's distance from the origin *)
let into_wedge (s : point2) r =
  s.pz <- Float.abs s.pz;
  if s.px < r *. cos36 then begin
    let far = s.px < r *. cos108 in
    let rot_sin = if far then sin144 else sin72 and rot_cos = if far then cos144 else cos72 in
    let rot_x = (s.px *. rot_cos) +. (s.pz *. rot_sin) and rot_z = (s.pz *. rot_cos) -. (s.px *. rot_sin) in
    s.px <- rot_x;
    s.pz <- Float.abs rot_z
  end

let[@inline] distance (s : point2) = sqrt ((s.px *. s.px) +. (s.pz *. s.pz))

let penrose rhombs centre (p : Vec.t) =
  let s = { px = p.x; pz = p.z } in
  let r = distance s in
  if r <= Precision.epsilon then 1.0
  else begin
    into_wedge s r;
    if rhombs then begin
      s.px <- s.px *. invphi;
      s.pz <- s.pz *. invphi
    end;
    let dist = Float.abs ((sin108 *. s.px) -. (cos108 *. s.pz)) /. cos18 in
    let depth = max 0 (c_int (ceil (log dist /. log sqrphi))) in
    let k = Float.pow invsqrphi (float_of_int depth) in
    s.px <- s.px *. k;
    s.pz <- s.pz *. k;
    if depth mod 2 <> 0 then begin
      let rot_x = (s.px *. cos36) +. (s.pz *. sin36) and rot_z = (s.pz *. cos36) -. (s.px *. sin36) in
      s.px <- rot_x;
      s.pz <- Float.abs rot_z
    end;
    let depth = depth * 2 in
    if centre then begin
      s.px <- s.px *. invphi;
      s.pz <- s.pz *. invphi;
      penrose_halves s.px s.pz (depth + 1) rhombs
    end
    else penrose_halves s.px s.pz depth rhombs
  end

(* Penrose's P1: pentagons (three kinds), stars, boats and diamonds, taken down the
   substitution as above; some tiles have a side (inside the quad, the wedge, side A) *)
type p1_tile = Pentagon1 | Pentagon2 | Pentagon3 | Star | Boat | Diamond

let pentagon_dist x = Float.abs (x -. (0.5 /. tan36)) *. 5.55 *. invphi

let penrose1_tiles x z depth =
  let s = { px = x; pz = z } in
  let depth = ref depth and tile = ref Pentagon1 and side = ref false in
  let result = ref 0. and fin = ref false in
  (* one level down: the tile the point is in, and the point in that tile's frame *)
  let go t sd px pz =
    tile := t;
    side := sd;
    s.px <- px *. phi;
    s.pz <- pz *. phi;
    decr depth
  in
  while not !fin do
    s.pz <- Float.abs s.pz;
    let deep = !depth > 0 in
    match !tile with
    | Pentagon1 ->
        into_wedge s (distance s);
        let px = s.px and pz = s.pz in
        if deep then
          if pz < ((px -. (0.5 /. tan36)) *. tan54) +. 0.5 then
            go Pentagon2 false (px -. (0.5 /. tan36) -. (invphi *. 0.5 *. cos72 /. sin36)) pz
          else go Star false ((px *. cos36) +. (pz *. sin36)) ((pz *. cos36) -. (px *. sin36))
        else begin
          fin := true;
          result := fmin (fmax ((1.0 /. 6.) -. (pentagon_dist px /. 6.)) 0.0) ((1.0 /. 6.) -. tiling_epsilon)
        end
    | Pentagon2 ->
        let px = s.px and pz = s.pz in
        if deep then
          if !side then
            if pz < (px -. (invsqrphi *. 0.5 /. sin36)) *. tan54 then go Pentagon1 false (px -. (0.5 /. sin36)) pz
            else if pz < (px -. (invsqrphi *. 0.5 /. sin36)) *. tan162 then go Diamond true (-.px) pz
            else
              go Pentagon2 true
                ((px *. cos108) -. (pz *. sin108) +. (invphi *. 0.5 /. sin36))
                ((pz *. cos108) +. (px *. sin108))
          else if pz < (px +. (0.5 /. sin36)) *. tan18 then
            go Diamond false (px +. (0.5 /. sin36) -. (invsqrphi *. 0.5 /. sin36)) pz
          else
            go Pentagon3 false
              (-.((px *. cos36) +. (pz *. sin36)) -. (cos72 *. 0.5 /. sin36))
              ((pz *. cos36) -. (px *. sin36) -. (sin72 *. 0.5 /. sin36))
        else begin
          into_wedge s (distance s);
          fin := true;
          result :=
            fmin
              (fmax ((2.0 /. 6.) -. (pentagon_dist s.px /. 6.)) ((1.0 /. 6.) +. tiling_epsilon))
              ((2.0 /. 6.) -. tiling_epsilon)
        end
    | Pentagon3 ->
        let px = s.px and pz = s.pz and wedge = !side in
        if deep then
          if wedge && px > invsqrphi *. 0.5 *. cos72 /. sin36 then
            go Pentagon2 true (-.(px -. (invsqrphi *. 0.5 *. cos72 /. sin36) -. (invphi *. 0.5 /. tan36))) pz
          else if (not wedge) && px < 0.5 *. cos108 /. sin36 then
            go Pentagon2 false ((px *. cos144) +. (pz *. sin144) -. (0.5 /. sin36)) ((pz *. cos144) -. (px *. sin144))
          else if (not wedge) && pz > (px -. (invsqrphi *. 0.5 /. sin36)) *. tan126 then
            go Pentagon3 false
              (-.((px *. cos36) -. (pz *. sin36)) -. (cos72 *. 0.5 /. sin36))
              ((pz *. cos36) +. (px *. sin36) -. (sin72 *. 0.5 /. sin36))
          else go Boat wedge px pz
        else begin
          into_wedge s (distance s);
          fin := true;
          result :=
            fmin
              (fmax ((3.0 /. 6.) -. (pentagon_dist s.px /. 6.)) ((2.0 /. 6.) +. tiling_epsilon))
              ((3.0 /. 6.) -. tiling_epsilon)
        end
    | Star ->
        let px = s.px and pz = s.pz in
        if deep then
          if px < invphi *. 0.5 /. tan36 then go Pentagon1 false px pz
          else go Pentagon3 true (-.(px -. (invphi /. tan36))) pz
        else begin
          fin := true;
          let dist = Float.abs ((sin162 *. (px -. (phi *. 0.5 /. sin36))) -. (cos162 *. pz)) *. 5.55 *. invphi in
          result :=
            fmin (fmax ((4.0 /. 6.) -. (dist /. 6.)) ((3.0 /. 6.) +. tiling_epsilon)) ((4.0 /. 6.) -. tiling_epsilon)
        end
    | Boat ->
        let px = s.px and pz = s.pz and wedge = !side in
        if deep then
          if wedge && px > phi *. 0.5 *. cos108 /. sin36 then go Pentagon1 false (-.px) pz
          else
            let rot_x = if wedge then px else (px *. cos72) -. (pz *. sin72)
            and rot_z = if wedge then pz else (pz *. cos72) +. (px *. sin72) in
            go Pentagon3 true (rot_x +. (0.5 /. sin36)) rot_z
        else begin
          fin := true;
          let dist1 = Float.abs (px -. (invphi *. 0.5 *. cos72 /. sin36)) *. 5.55 *. invphi in
          s.px <- -.px;
          into_wedge s (distance s);
          let dist2 = Float.abs ((sin162 *. (s.px -. (phi *. 0.5 /. sin36))) -. (cos162 *. s.pz)) *. 5.55 *. invphi in
          result :=
            fmin
              (max3 ((5.0 /. 6.) -. (dist1 /. 6.)) ((5.0 /. 6.) -. (dist2 /. 6.)) ((4.0 /. 6.) +. tiling_epsilon))
              ((5.0 /. 6.) -. tiling_epsilon)
        end
    | Diamond ->
        let px = s.px and pz = s.pz in
        if deep then if !side then go Pentagon1 false px pz else go Pentagon3 true px pz
        else begin
          fin := true;
          let dist = Float.abs ((sin18 *. (px +. (invphi *. 0.5 /. sin36))) -. (cos18 *. pz)) *. 5.55 *. invphi in
          result :=
            fmin (fmax ((6.0 /. 6.) -. (dist /. 6.)) ((5.0 /. 6.) +. tiling_epsilon)) ((6.0 /. 6.) -. tiling_epsilon)
        end
  done;
  !result

let penrose1 (p : Vec.t) =
  let s = { px = p.x; pz = p.z } in
  let r = distance s in
  if r <= Precision.epsilon then 1.0
  else begin
    into_wedge s r;
    let dist = s.px *. 2. *. tan36 in
    let depth = max 0 (c_int (ceil (log dist /. log (sqrphi *. sqrphi)))) in
    let k = Float.pow (invsqrphi *. invsqrphi) (float_of_int depth) in
    penrose1_tiles (s.px *. k) (s.pz *. k) (depth * 4)
  end

(* the tilings by number: 1 squares, 2 hexagons, 3 triangles, 4 lozenges, 5 rhombs, 6 and 18
   rectangles, 7 octagons and squares, 8 and 21 squares and triangles, 9 hexagons and
   triangles, 10 offset squares, 11 and 12 squares and rectangles, 13 and 14 squares at 45° in
   squares, 15 squares of two sizes, 16 and 17 hexagons, squares and triangles, 19 and 20
   hexagons and triangles in shifted rows, 22 dodecagons and triangles, 23 and 24 dodecagons,
   hexagons and squares, 25 Penrose's P1, 26 his kites and darts, 27 his rhombs; any other
   number is 1, as in POV-Ray's switch *)
let value n (p : Vec.t) =
  match n with
  | 27 -> penrose true false p
  | 26 -> penrose false false p
  | 25 -> penrose1 p
  | 24 -> dodeca_hex_n true p
  | 23 -> dodeca_hex_n false p
  | 22 -> dodeca_tri p
  | 21 -> square_tri p
  | 20 -> hexa_tri_left p
  | 19 -> hexa_tri_right p
  | 18 -> rectangle_pair p
  | 17 -> hexa_square_triangle_n true p
  | 16 -> hexa_square_triangle_n false p
  | 15 -> square_double p
  | 14 -> square_internal_5 p
  | 13 -> square_internal p
  | 12 -> rectangle_square p
  | 11 -> square_rectangle p
  | 10 -> square_offset p
  | 9 -> hexa_triangle p
  | 8 -> square_triangle p
  | 7 -> octa_square p
  | 6 -> rectangle p
  | 5 -> rhombus p
  | 4 -> lozenge p
  | 3 -> triangle p
  | 2 -> hexagon p
  | _ -> square p
