(* CSG kept whole: docs/povray-rules.md §16, POV-Ray's CSG (union, merge, intersection) and clipped_by. *)

open Compiled

(* a predicate on one constructor: shapes added later are primitives *)
let is_csg = function Csg _ -> true | _ -> false

(* Keeps the hits [start, e) of member [skip] whose point is Inside ([want]) or outside every other
   member, in place; [reverse]d when they come off a local stack. Returns the new end. *)
let keep_hits ~inside (w : Scratch.t) (members : member array) ~skip ~want ~reverse start e =
  let width = Scratch.hit_width in
  let nm = Array.length members in
  let k = ref start in
  for j = start to e - 1 do
    let h = w.hits.room and b = j * width in
    let p = Vec.make h.(b + 3) h.(b + 4) h.(b + 5) in
    let keep = ref true and i = ref 0 in
    while !keep && !i < nm do
      if !i <> skip && inside w.mesh_stack members.(!i) p <> want then keep := false;
      incr i
    done;
    if !keep then begin
      if !k <> j then Array.blit h b h (!k * width) width;
      incr k
    end
  done;
  if reverse then begin
    let h = w.hits.room in
    let a = ref start and z = ref (!k - 1) in
    while !a < !z do
      for f = 0 to width - 1 do
        let x = h.((!a * width) + f) in
        h.((!a * width) + f) <- h.((!z * width) + f);
        h.((!z * width) + f) <- x
      done;
      incr a;
      decr z
    done
  end;
  !k

(* Ray_In_Bound: the ray meets the object only if it meets every bounding object (members 1 …)
   at a depth of at least MIN_ISECT_DEPTH, their boxes tested first as Find_Intersection does, or
   starts inside it. The bounding objects' hits are pushed above [n] and dropped. *)
let in_bound ~all_hits ~inside (w : Scratch.t) (members : member array) o d n =
  let stats = w.stats and nm = Array.length members in
  let rec from k =
    k >= nm
    ||
    let b = members.(k) in
    Stats.test stats Stats.bounding_object;
    let met =
      (Array.length b.pbox = 0 || Pov_box.entry b.pbox o d < infinity) && all_hits w b o d Precision.min_isect_depth n > n
    in
    (met || inside w.mesh_stack b o)
    && begin
         Stats.hit stats Stats.bounding_object;
         from (k + 1)
       end
  in
  from 1

let hits ~all_hits ~inside (w : Scratch.t) (c : csg) o d lo n =
  let stats = w.stats and n0 = n in
  let members = c.members in
  let nm = Array.length members in
  let n =
    match c.kind with
    | Union ->
        Stats.test stats Stats.csg_union;
        let n = ref n in
        Array.iter (fun m -> n := all_hits w m o d lo !n) members;
        !n
    | Intersection | Merge ->
        (match c.kind with
        | Intersection -> Stats.test stats Stats.csg_intersection
        | Merge | Union | Clipped | Bounded | Boxed -> Stats.test stats Stats.csg_merge);
        let want = match c.kind with Intersection -> true | Merge | Union | Clipped | Bounded | Boxed -> false in
        let n = ref n in
        for k = 0 to nm - 1 do
          let start = !n in
          let e = all_hits w members.(k) o d lo start in
          n := keep_hits ~inside w members ~skip:k ~want ~reverse:true start e
        done;
        !n
    | (Clipped | Bounded | Boxed) when nm = 0 -> n
    | Bounded -> if in_bound ~all_hits ~inside w members o d n then all_hits w members.(0) o d lo n else n
    | Boxed -> all_hits w members.(0) o d lo n
    | Clipped -> (
        match members.(0).shape with
        | Csg { kind = Union; members = um; _ } ->
            Stats.test stats Stats.csg_union;
            let n = ref n in
            Array.iter
              (fun u ->
                let start = !n in
                let e = all_hits w u o d lo start in
                n := keep_hits ~inside w members ~skip:0 ~want:true ~reverse:true start e)
              um;
            if !n > n0 then Stats.hit stats Stats.csg_union;
            !n
        | _ ->
            (* a clipped primitive or a clipped merge or intersection *)
            let e = all_hits w members.(0) o d lo n in
            keep_hits ~inside w members ~skip:0 ~want:true ~reverse:false n e)
  in
  (if n > n0 then
     match c.kind with
     | Union -> Stats.hit stats Stats.csg_union
     | Intersection -> Stats.hit stats Stats.csg_intersection
     | Merge -> Stats.hit stats Stats.csg_merge
     | Clipped | Bounded | Boxed -> ());
  n

let nearest_kept ~all_hits ~inside (w : Scratch.t) c o d lo =
  w.report_count <- 0;
  let n = hits ~all_hits ~inside w c o d lo 0 in
  let h = w.hits.room and width = Scratch.hit_width in
  let best = ref infinity and bj = ref (-1) in
  for j = n - 1 downto 0 do
    let t = h.(j * width) in
    if t < !best then begin best := t; bj := j end
  done;
  if !bj >= 0 then begin
    w.part <- int_of_float h.((!bj * width) + 1);
    w.leaf <- int_of_float h.((!bj * width) + 2);
    (* the member's report of the hit kept *)
    w.reported <- Scratch.hit_report w !bj
  end;
  !best

let depth ~all_hits ~inside (w : Scratch.t) c o d lo =
  if (not w.robust) && Array.length c.cbox > 0 && Pov_box.entry c.cbox o d = infinity then infinity
  else nearest_kept ~all_hits ~inside w c o d lo

let depth_unboxed = nearest_kept

let inside ~inside stack c p =
  match c.kind with
  | Union | Merge -> Array.exists (fun m -> inside stack m p) c.members
  | Intersection | Clipped -> Array.for_all (fun m -> inside stack m p) c.members
  | Bounded | Boxed -> Array.length c.members > 0 && inside stack c.members.(0) p

let lone_inverted c =
  match c with
  | { kind = Intersection; members = [| m |]; _ } when m.inverted && not (is_csg m.shape) -> Some m
  | _ -> None

(* The end of Parse_Object_Mods: the box of the bounding objects (members 1 …, the inverted ones
   left out), their single-precision corners overlapped in double precision, replaces the
   object's box when its volume, multiplied out in single precision, is the smaller. An unbounded
   box is POV-Ray's huge one. *)
let huge_box = [| -1e10; -1e10; -1e10; 2e10; 2e10; 2e10 |]

let bounded_box (c : csg) =
  let f32 = Precision.f32 in
  let own = if Array.length c.members.(0).pbox = 0 then huge_box else c.members.(0).pbox in
  let lo = Array.make 3 (-2e10) and hi = Array.make 3 2e10 in
  for k = 1 to Array.length c.members - 1 do
    let m = c.members.(k) in
    if not m.inverted then begin
      let b = if Array.length m.pbox = 0 then huge_box else m.pbox in
      for i = 0 to 2 do
        lo.(i) <- Float.max lo.(i) b.(i);
        hi.(i) <- Float.min hi.(i) (f32 (b.(i) +. b.(i + 3)))
      done
    end
  done;
  let box = Pov_box.of_min_max lo hi in
  if Pov_box.volume box < Pov_box.volume own then box else own

(* CSG::Compute_BBox of an intersection: the overlap of its members' boxes ([member_box]), the
   inverted members and height fields left out, the quadrics taken last *)
let intersection_bounds ~member_box c =
  let overlap a b = Array.init 6 (fun i -> if i < 3 then Float.max a.(i) b.(i) else Float.min a.(i) b.(i)) in
  let is_quadric (m : member) = match m.shape with Quadric _ -> true | _ -> false in
  (* CSG::Compute_BBox leaves an intersection's height fields out too *)
  let is_hfield (m : member) = match (c.kind, m.shape) with Intersection, Height_field _ -> true | _ -> false in
  let b =
    Array.fold_left
      (fun acc (m : member) ->
        match (m.inverted || is_quadric m || is_hfield m, acc, member_box m) with
        | false, None, Some b -> Some b
        | false, Some a, Some b -> Some (overlap a b)
        | false, acc, None | true, acc, _ -> acc)
      None c.members
  in
  (* CSG::Compute_BBox takes the quadrics last, each bounded within the others' box
     (Quadric::Compute_BBox with that box as its clip); clipped_by does the same *)
  let b =
    Array.fold_left
      (fun acc (m : member) ->
        match (m.inverted, m.shape) with
        | false, Quadric q -> (
            let lo, hi = match acc with Some a -> (Array.sub a 0 3, Array.sub a 3 3) | None -> (Array.make 3 (-2e10), Array.make 3 2e10) in
            match (acc, Quadric.bounds_within q lo hi) with
            | _, None -> acc
            | None, Some qb -> Some qb
            | Some a, Some qb -> Some (overlap a qb))
        | _ -> acc)
      b c.members
  in
  (* an empty overlap: nothing can be hit; POV-Ray then keeps its unbounded box *)
  Option.bind b (fun b -> if b.(0) > b.(3) || b.(1) > b.(4) || b.(2) > b.(5) then None else Some b)

let bounds ~bounds c =
  match (c.kind, lone_inverted c) with
  | _, Some m -> bounds m.shape
  | (Bounded | Boxed), None when Array.length c.members = 0 -> None
  | (Bounded | Boxed), None ->
      let b = bounded_box c in
      if b == c.members.(0).pbox then bounds c.members.(0).shape
      else if b == huge_box then None
      else Some [| b.(0); b.(1); b.(2); Precision.f32 (b.(0) +. b.(3)); Precision.f32 (b.(1) +. b.(4)); Precision.f32 (b.(2) +. b.(5)) |]
  | (Union | Merge), None ->
      Array.fold_left
        (fun acc (m : member) ->
          match (acc, bounds m.shape) with
          | Some a, Some b -> Some (Array.init 6 (fun i -> if i < 3 then Float.min a.(i) b.(i) else Float.max a.(i) b.(i)))
          | None, _ | _, None -> None)
        (Some [| infinity; infinity; infinity; neg_infinity; neg_infinity; neg_infinity |])
        c.members
      |> Option.map (fun b -> if b.(0) > b.(3) then [| 0.; 0.; 0.; 0.; 0.; 0. |] else b)
  | (Intersection | Clipped), None -> intersection_bounds ~member_box:(fun (m : member) -> bounds m.shape) c

let union_box boxes =
  (* the members' single-precision boxes, their upper corners added in double precision; a box
     longer than CRITICAL_LENGTH (1e6) on any axis is POV-Ray's huge one *)
  let lo = Array.make 3 2e10 and hi = Array.make 3 (-2e10) in
  List.iter
    (fun b ->
      let b = if Array.length b = 0 then huge_box else b in
      for i = 0 to 2 do
        lo.(i) <- Float.min lo.(i) b.(i);
        hi.(i) <- Float.max hi.(i) (b.(i) +. b.(i + 3))
      done)
    boxes;
  if lo.(0) > hi.(0) || lo.(1) > hi.(1) || lo.(2) > hi.(2) then [||]
  else
    let b = Pov_box.of_min_max lo hi in
    if b.(3) > 1e6 || b.(4) > 1e6 || b.(5) > 1e6 then [||] else b

let pov_box ~pov_box c =
  match (c.kind, lone_inverted c) with
  | _, Some m -> pov_box m.shape
  | (Bounded | Boxed), None when Array.length c.members = 0 -> [||]
  | (Bounded | Boxed), None ->
      let b = bounded_box c in
      if b == huge_box then [||] else b
  | (Union | Merge), None when Array.length c.cbox > 0 -> c.cbox
  | (Union | Merge), None -> union_box (Array.to_list (Array.map (fun (m : member) -> m.pbox) c.members))
  | (Intersection | Clipped), None -> (
      (* the members' POV-Ray boxes, as POV-Ray keeps them (not the tighter ones povml's own
         hierarchy uses) *)
      let member_box (m : member) =
        let b = m.pbox in
        if Array.length b = 0 then None else Some [| b.(0); b.(1); b.(2); b.(0) +. b.(3); b.(1) +. b.(4); b.(2) +. b.(5) |]
      in
      match intersection_bounds ~member_box c with
      | None -> [||]
      | Some b -> Pov_box.of_min_max (Array.sub b 0 3) (Array.sub b 3 3))

let magnitude c = Array.fold_left (fun m (o : member) -> Float.max m o.mag) 0. c.members
