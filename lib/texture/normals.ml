(* Perturbed normals (normal.cpp). To be written. *)

let perturb (_gen : int) (_ : Scene.normal) (_ : Vec.t) (_ : Patterns.hit) (n : Vec.t) : Vec.t = ignore n; failwith "Normals.perturb"
