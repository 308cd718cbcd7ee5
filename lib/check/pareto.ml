(* Pareto fronts: the settings no other beats on both error and time. *)

let front cost xs =
  let sorted = List.stable_sort (fun a b -> compare (cost a) (cost b)) xs in
  let _, kept =
    List.fold_left
      (fun (best, acc) x ->
        let _, e = cost x in
        if e < best then (e, x :: acc) else (best, acc))
      (infinity, []) sorted
  in
  List.rev kept
