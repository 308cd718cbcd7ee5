type obj = {
  shape : Scene.shape;
  texture : Scene.texture option;
  interior : Scene.interior option;
  no_shadow : bool;
  oloc : Loc.t;
}

type t =
  | Float of float
  | Vector of float array
  | Colour of float array
  | String of string
  | Pigment of Scene.pigment
  | Finish of Scene.finish
  | Texture of Scene.texture
  | Interior of Scene.interior
  | Object of obj

let kind_name = function
  | Float _ -> "a float"
  | Vector a -> Printf.sprintf "a %d-term vector" (Array.length a)
  | Colour _ -> "a colour"
  | String _ -> "a string"
  | Pigment _ -> "a pigment"
  | Finish _ -> "a finish"
  | Texture _ -> "a texture"
  | Interior _ -> "an interior"
  | Object _ -> "an object"

let terms = function
  | Float _ -> 1
  | Vector a | Colour a -> Array.length a
  | String _ | Pigment _ | Finish _ | Texture _ | Interior _ | Object _ -> 0

(* POVRAY-3.7 §11.2: a float is replicated into every term, a shorter vector is padded with zeros. *)
let promote v n =
  match v with
  | Float f -> Array.make n f
  | Vector a | Colour a -> Array.init n (fun i -> if i < Array.length a then a.(i) else 0.)
  | String _ | Pigment _ | Finish _ | Texture _ | Interior _ | Object _ -> invalid_arg "Value.promote"

let numeric v = terms v > 0

let arith op a b =
  match (a, b) with
  | Float x, Float y -> Some (Float (op x y))
  | _ when numeric a && numeric b ->
      let is_colour = (match a with Colour _ -> true | _ -> false) || match b with Colour _ -> true | _ -> false in
      let n = if is_colour then 5 else max (terms a) (terms b) in
      let pa = promote a n and pb = promote b n in
      let r = Array.init n (fun i -> op pa.(i) pb.(i)) in
      Some (if is_colour then Colour r else Vector r)
  | _ -> None

let map f = function
  | Float x -> Some (Float (f x))
  | Vector a -> Some (Vector (Array.map f a))
  | Colour a -> Some (Colour (Array.map f a))
  | String _ | Pigment _ | Finish _ | Texture _ | Interior _ | Object _ -> None
