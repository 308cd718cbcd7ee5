(* Growable arrays, for the lists of a mesh. With a capacity given (mesh2 announces its counts) the
   array is made once at that size and handed over as it is; otherwise the values go into chunks
   and [to_array] copies them once, so growing never holds more than the values and one copy. *)

(* [chunks.(0)] has the first size (the capacity, or 1024), every later chunk [chunk] values *)
type 'a t = { fill : 'a; mutable chunks : 'a array array; mutable n : int; mutable len : int }

let chunk = 65536

let create ?capacity x =
  let first = match capacity with Some c -> max 16 c | None -> 1024 in
  { fill = x; chunks = [| Array.make first x |]; n = 1; len = 0 }

let first g = Array.length g.chunks.(0)

let push g x =
  let f = first g in
  let c, i = if g.len < f then (0, g.len) else (1 + ((g.len - f) / chunk), (g.len - f) mod chunk) in
  if c = g.n then begin
    if g.n = Array.length g.chunks then g.chunks <- Array.append g.chunks (Array.make g.n [||]);
    g.chunks.(c) <- Array.make chunk g.fill;
    g.n <- g.n + 1
  end;
  Array.unsafe_set g.chunks.(c) i x;
  g.len <- g.len + 1

let get g i =
  let f = first g in
  if i < f then g.chunks.(0).(i) else g.chunks.(1 + ((i - f) / chunk)).((i - f) mod chunk)

let to_array g =
  if g.n = 1 && g.len = first g then g.chunks.(0)
  else begin
    let a = Array.make g.len g.fill in
    let at = ref 0 in
    for c = 0 to g.n - 1 do
      let k = min (Array.length g.chunks.(c)) (g.len - !at) in
      Array.blit g.chunks.(c) 0 a !at k;
      at := !at + k
    done;
    a
  end
