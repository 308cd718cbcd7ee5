(* POV-Ray 3.7's noise and turbulence (texture.cpp). To be written. *)

let noise _gen (_ : Vec.t) = failwith "Noise.noise"
let dnoise (_ : Vec.t) : Vec.t = failwith "Noise.dnoise"
let turbulence (_ : Scene.turb) _gen (_ : Vec.t) = failwith "Noise.turbulence"
let dturbulence (_ : Scene.turb) (_ : Vec.t) : Vec.t = failwith "Noise.dturbulence"
let hash3d (_ : int) (_ : int) (_ : int) = failwith "Noise.hash3d"
let hash2d (_ : int) (_ : int) = failwith "Noise.hash2d"
let random_double (_ : int) = failwith "Noise.random_double"
