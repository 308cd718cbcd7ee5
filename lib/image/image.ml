(* Float images: the linear colours the tracer produced, kept in single precision. *)

type t = { width : int; height : int; data : (float, Bigarray.float32_elt, Bigarray.c_layout) Bigarray.Array1.t }

let create width height =
  let data = Bigarray.Array1.create Bigarray.float32 Bigarray.c_layout (3 * width * height) in
  Bigarray.Array1.fill data 0.;
  { width; height; data }

let get img x y =
  let i = 3 * ((y * img.width) + x) in
  (Bigarray.Array1.get img.data i, Bigarray.Array1.get img.data (i + 1), Bigarray.Array1.get img.data (i + 2))

let set img x y r g b =
  let i = 3 * ((y * img.width) + x) in
  Bigarray.Array1.set img.data i r;
  Bigarray.Array1.set img.data (i + 1) g;
  Bigarray.Array1.set img.data (i + 2) b

let channel img i = Bigarray.Array1.get img.data i
let channels img = Bigarray.Array1.dim img.data
