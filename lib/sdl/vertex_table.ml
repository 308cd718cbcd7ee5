(* Vertices (or normals) of a mesh { } merged when equal, as POV-Ray merges them: an open
   addressing table over the stored single-precision triples. *)

type t = { store : float Growable.t; mutable slots : int array; mutable count : int }

let create () = { store = Growable.create 0.; slots = Array.make 1024 (-1); count = 0 }

let hash x y z = Hashtbl.hash (Int64.bits_of_float x, Int64.bits_of_float y, Int64.bits_of_float z)

let coord t i = Growable.get t.store i

let rec insert t x y z =
  let mask = Array.length t.slots - 1 in
  let rec probe h =
    let k = t.slots.(h) in
    if k < 0 then begin
      t.slots.(h) <- t.count;
      Growable.push t.store x; Growable.push t.store y; Growable.push t.store z;
      t.count <- t.count + 1;
      t.count - 1
    end
    else if coord t (3 * k) = x && coord t ((3 * k) + 1) = y && coord t ((3 * k) + 2) = z then k
    else probe ((h + 1) land mask)
  in
  if 2 * (t.count + 1) > Array.length t.slots then begin
    let n = 2 * Array.length t.slots in
    let slots = Array.make n (-1) in
    for k = 0 to t.count - 1 do
      let rec place h = if slots.(h) < 0 then slots.(h) <- k else place ((h + 1) land (n - 1)) in
      place (hash (coord t (3 * k)) (coord t ((3 * k) + 1)) (coord t ((3 * k) + 2)) land (n - 1))
    done;
    t.slots <- slots;
    insert t x y z
  end
  else probe (hash x y z land mask)

let to_array t = Growable.to_array t.store
