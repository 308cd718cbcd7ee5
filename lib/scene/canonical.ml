(* The set-up of cylinders, cones and discs (docs/povray-rules.md §15.2–§15.4): the transform from each one's
   canonical space to the shape as written, computed in POV-Ray's operation order
   (Cone::Compute_Cone_Data, Compute_Cylinder_Data, Disc::Compute_Disc), since the last bit of a
   matrix entry can decide a pixel. *)

(* VLength, then VInverseScaleEq: times the reciprocal of the length *)
let unit_and_length (v : Vec.t) =
  let len = sqrt ((v.x *. v.x) +. (v.y *. v.y) +. (v.z *. v.z)) in
  let k = 1. /. len in
  (Vec.make (v.x *. k) (v.y *. k) (v.z *. k), len)

(* §15.2: the axis from P2 to P1; P2 maps to z = 0, P1 to z = 1 *)
let cylinder_trans ~p1 ~p2 radius =
  let axis, len = unit_and_length (Vec.sub p1 p2) in
  if len < Precision.epsilon then None else Some (fst (Transform.coordinate p2 axis radius len))

let cylinder ~p1 ~p2 ~radius ~closed : Scene.shape option =
  Option.map
    (fun trans -> Scene.Cone { p1; r1 = radius; p2; r2 = radius; cylinder = true; dist = 0.; closed; trans })
    (cylinder_trans ~p1 ~p2 radius)

let cone ~p1 ~r1 ~p2 ~r2 ~closed : Scene.shape option =
  let axis, len = unit_and_length (Vec.sub p1 p2) in
  let as_cylinder ~p1 ~p2 r =
    Option.map
      (fun trans -> Scene.Cone { p1 = p1; r1; p2 = p2; r2; cylinder = true; dist = 0.; closed; trans })
      (cylinder_trans ~p1 ~p2 r)
  in
  if len < Precision.epsilon then None
  else if Float.abs (r1 -. r2) < Precision.epsilon then as_cylinder ~p1 ~p2 r1
  else
    (* §15.3: the bigger end at the top (z = 1), the apex of the full cone at z = 0 *)
    let big, rb, small, rs, axis =
      if r1 < r2 then (p2, r2, p1, r1, Vec.make (axis.x *. -1.) (axis.y *. -1.) (axis.z *. -1.)) else (p1, r1, p2, r2, axis)
    in
    let h = rs *. len /. (rb -. rs) in
    let origin = Vec.sub small (Vec.make (axis.x *. h) (axis.y *. h) (axis.z *. h)) in
    let tlen = h +. len in
    if (rb -. rs) *. len /. tlen < Precision.epsilon then
      (* so thin a taper that POV-Ray takes it for a cylinder of the big radius *)
      Option.map
        (fun trans -> Scene.Cone { p1; r1; p2; r2; cylinder = true; dist = 0.; closed; trans })
        (cylinder_trans ~p1:big ~p2:small rb)
    else
      let trans, _ = Transform.coordinate origin axis rb tlen in
      Some (Scene.Cone { p1; r1; p2; r2; cylinder = false; dist = h /. tlen; closed; trans })

let disc ~centre ~normal ~radius ~hole : Scene.shape =
  let n = Transform.normalize normal in
  let trans, n = Transform.coordinate centre n 1. 1. in
  Scene.Disc { centre; normal = n; radius; hole; trans }
