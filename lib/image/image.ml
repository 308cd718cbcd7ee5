(* Float images: the linear colours the tracer produced. *)

type t = { width : int; height : int; data : Float.Array.t }

let create width height = { width; height; data = Float.Array.make (3 * width * height) 0. }

let get img x y =
  let i = 3 * ((y * img.width) + x) in
  (Float.Array.get img.data i, Float.Array.get img.data (i + 1), Float.Array.get img.data (i + 2))

let set img x y r g b =
  let i = 3 * ((y * img.width) + x) in
  Float.Array.set img.data i r;
  Float.Array.set img.data (i + 1) g;
  Float.Array.set img.data (i + 2) b
