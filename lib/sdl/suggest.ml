(* "Did you mean …": the names nearest a misspelt one by edit distance, case ignored. *)

let distance a b =
  let la = String.length a and lb = String.length b in
  let prev = Array.init (lb + 1) (fun j -> j) and cur = Array.make (lb + 1) 0 in
  for i = 1 to la do
    cur.(0) <- i;
    for j = 1 to lb do
      let cost = if Char.lowercase_ascii a.[i - 1] = Char.lowercase_ascii b.[j - 1] then 0 else 1 in
      cur.(j) <- min (min (prev.(j) + 1) (cur.(j - 1) + 1)) (prev.(j - 1) + cost)
    done;
    Array.blit cur 0 prev 0 (lb + 1)
  done;
  prev.(lb)

let nearest name candidates =
  if String.length name > 64 then []
  else
    let limit = max 1 (String.length name / 3) in
    candidates
    |> List.sort_uniq compare
    |> List.filter_map (fun c ->
           if String.length c > 64 then None
           else
             let d = distance name c in
             if d <= limit && c <> name then Some (d, c) else None)
    |> List.sort compare
    |> List.filteri (fun i _ -> i < 3)
    |> List.map snd
