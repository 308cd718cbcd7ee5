(* Splines of the scene language (backend/math/splines.cpp, Parse_Spline of parser/express.cpp).
   Every formula keeps POV-Ray's operations in its order: the values must be the same doubles. *)

type kind = Linear | Quadratic | Cubic | Natural

type t = {
  kind : kind;
  times : float array;  (** increasing *)
  values : float array array;  (** per entry, POV-Ray's five terms *)
  second : float array array;
      (** per entry, the five second derivatives of the natural spline (Precompute_Cubic_Coeffs),
          a function of the entries alone: POV-Ray computes them again after any insertion *)
  terms : int;
}

let all_terms = 5

(* the time of a slot past the last entry: Create_Spline and Insert_Spline_Entry mark the unused
   slots with it, and Insert_Spline_Entry reads the first of them *)
let unused_time = -1e6

(* findt: the index of the first of the [n] times not below [time] (0 up to the first time, [n]
   from the last on), by POV-Ray's bisection from the middle, which decides where a NaN goes *)
let segment times n time =
  let rec bracket lower upper =
    if upper - lower > 1 then
      let mid = lower + ((upper - lower) / 2) in
      if time > times.(mid) then bracket mid upper else bracket lower mid
    else upper
  in
  if n = 0 || time <= times.(0) then 0
  else if time >= times.(n - 1) then n
  else
    let half = n / 2 in
    if time > times.(half) then bracket half (n - 1) else bracket 0 half

(* ---------------------------------------------------------------------------------------------- *)
(* Building: the entries inserted one by one into a growing table, as Insert_Spline_Entry does *)

type table = { mutable t_times : float array; mutable t_values : float array array; mutable count : int }

let table_of times values = { t_times = Array.copy times; t_values = Array.copy values; count = Array.length times }

let grow table =
  if table.count = Array.length table.t_times then begin
    let capacity = max 16 (2 * table.count) in
    let times = Array.make capacity unused_time and values = Array.make capacity [||] in
    Array.blit table.t_times 0 times 0 table.count;
    Array.blit table.t_values 0 values 0 table.count;
    table.t_times <- times;
    table.t_values <- values
  end

let insert table time value =
  let n = table.count in
  let i = segment table.t_times n time in
  let slot_time = if i < n then table.t_times.(i) else unused_time in
  if n <> 0 && (slot_time = time || (i = n && table.t_times.(n - 1) = time)) then begin
    (* a time already there: its value is replaced, but when [i] is the slot past the end
       (the last entry's time, or -1e6) POV-Ray writes it there, where it is lost *)
    if i < n then table.t_values.(i) <- value
  end
  else begin
    grow table;
    Array.blit table.t_times i table.t_times (i + 1) (n - i);
    Array.blit table.t_values i table.t_values (i + 1) (n - i);
    table.t_times.(i) <- time;
    table.t_values.(i) <- value;
    table.count <- n + 1
  end

(* Parse_Spline reads each value into one five-term buffer: a float fills two terms (Parse_Express
   promotes it), a vector its own; the others keep what the entry before left there *)
let fill_buffer buffer (value : float array) =
  match Array.length value with
  | 1 ->
      buffer.(0) <- value.(0);
      buffer.(1) <- value.(0)
  | n when n <= all_terms -> Array.blit value 0 buffer 0 n
  | _ -> invalid_arg "Spline: a value has 1 to 5 terms"

let written_terms (value : float array) =
  if Array.length value = 0 then invalid_arg "Spline: a value has 1 to 5 terms" else max 2 (Array.length value)

(* Precompute_Cubic_Coeffs: the second derivatives of the natural cubic through the entries, 0 at
   both ends, for each of the five terms *)
let second_derivatives times values =
  let n = Array.length times in
  let second = Array.init n (fun _ -> Array.make all_terms 0.) in
  if n >= 3 then begin
    let h = Array.init (n - 1) (fun i -> times.(i + 1) -. times.(i)) in
    let u = Array.make (n - 1) 0. and v = Array.make (n - 1) 0. in
    for k = 0 to all_terms - 1 do
      let b = Array.init (n - 1) (fun i -> (values.(i + 1).(k) -. values.(i).(k)) /. h.(i)) in
      u.(1) <- 2. *. (h.(0) +. h.(1));
      v.(1) <- 6. *. (b.(1) -. b.(0));
      for i = 2 to n - 2 do
        u.(i) <- (2. *. (h.(i) +. h.(i - 1))) -. (h.(i - 1) *. h.(i - 1) /. u.(i - 1));
        v.(i) <- (6. *. (b.(i) -. b.(i - 1))) -. (h.(i - 1) *. v.(i - 1) /. u.(i - 1))
      done;
      for i = n - 2 downto 1 do
        second.(i).(k) <- (v.(i) -. (h.(i) *. second.(i + 1).(k))) /. u.(i)
      done
    done
  end;
  second

let finish kind table terms =
  let times = Array.sub table.t_times 0 table.count and values = Array.sub table.t_values 0 table.count in
  { kind; times; values; second = second_derivatives times values; terms }

let insert_all table terms entries =
  let buffer = Array.make all_terms 0. in
  List.fold_left
    (fun terms (time, value) ->
      let terms = max terms (written_terms value) in
      fill_buffer buffer value;
      insert table time (Array.copy buffer);
      terms)
    terms entries

let make kind entries =
  (match entries with [] -> invalid_arg "Spline.make: no entries" | _ :: _ -> ());
  let table = { t_times = [||]; t_values = [||]; count = 0 } in
  let terms = insert_all table 2 entries in
  finish kind table terms

let add s entries =
  let table = table_of s.times s.values in
  let terms = insert_all table s.terms entries in
  finish s.kind table terms

let terms s = s.terms
let kind s = s.kind
let entries s = Array.mapi (fun i time -> (time, Array.sub s.values.(i) 0 s.terms)) s.times
let with_kind s kind = { s with kind }

(* ---------------------------------------------------------------------------------------------- *)
(* Interpolation of term [k] (splines.cpp) *)

(* linear_interpolate between entries [i] and [i + 1] *)
let linear s i k p =
  let p1 = s.times.(i) and p2 = s.times.(i + 1) in
  let v1 = s.values.(i).(k) and v2 = s.values.(i + 1).(k) in
  ((p -. p1) *. (v2 -. v1) /. (p2 -. p1)) +. v1

(* quadratic_interpolate: the parabola through entries [i - 1], [i] and [i + 1], as a p² + b p + c *)
let quadratic s i k p =
  let p1 = s.times.(i - 1) and p2 = s.times.(i) and p3 = s.times.(i + 1) in
  let v1 = s.values.(i - 1).(k) and v2 = s.values.(i).(k) and v3 = s.values.(i + 1).(k) in
  let n = (p2 -. p1) *. (p3 -. p1) *. (p3 -. p2) in
  let a = ((-.p2 *. v1) +. (p3 *. v1) +. (p1 *. v2) -. (p3 *. v2) -. (p1 *. v3) +. (p2 *. v3)) /. n in
  let b =
    ((p2 *. p2 *. v1) -. (p3 *. p3 *. v1) -. (p1 *. p1 *. v2) +. (p3 *. p3 *. v2) +. (p1 *. p1 *. v3) -. (p2 *. p2 *. v3)) /. n
  in
  let c =
    ((-.p2 *. p2 *. p3 *. v1) +. (p2 *. p3 *. p3 *. v1) +. (p1 *. p1 *. p3 *. v2) -. (p1 *. p3 *. p3 *. v2)
    -. (p1 *. p1 *. p2 *. v3) +. (p1 *. p2 *. p2 *. v3))
    /. n
  in
  (((a *. p) +. b) *. p) +. c

(* natural_interpolate between entries [i] and [i + 1], with the second derivatives *)
let natural s i k p =
  let p0 = s.times.(i) and v0 = s.values.(i).(k) and v1 = s.values.(i + 1).(k) in
  let c0 = s.second.(i).(k) and c1 = s.second.(i + 1).(k) in
  let h = s.times.(i + 1) -. p0 in
  let tmp = (c0 /. 2.0) +. ((p -. p0) *. (c1 -. c0) /. (6.0 *. h)) in
  let tmp = (-.(h /. 6.0) *. (c1 +. (2.0 *. c0))) +. ((v1 -. v0) /. h) +. ((p -. p0) *. tmp) in
  v0 +. ((p -. p0) *. tmp)

(* catmull_rom_interpolate between entries [i] and [i + 1], with the tangents through [i - 1] and
   [i + 2] *)
let catmull_rom s i k p =
  let t = s.times and v = s.values in
  let dt = t.(i + 1) -. t.(i) in
  let u = (p -. t.(i)) /. dt in
  let slope j = (v.(j + 1).(k) -. v.(j).(k)) /. (t.(j + 1) -. t.(j)) in
  let dp0 = (slope (i - 1) +. slope i) /. 2.0 *. dt in
  let dp1 = (slope (i + 1) +. slope i) /. 2.0 *. dt in
  (v.(i).(k) *. ((2. *. u *. u *. u) -. (3. *. u *. u) +. 1.))
  +. (v.(i + 1).(k) *. ((3. *. u *. u) -. (2. *. u *. u *. u)))
  +. (dp0 *. ((u *. u *. u) -. (2. *. u *. u) +. u))
  +. (dp1 *. ((u *. u *. u) -. (u *. u)))

(* Get_Spline_Val's rule for term [k], [i] being the entry ending the segment of [p] *)
let term s last i k p =
  let v j = s.values.(j).(k) in
  match s.kind with
  | Linear -> if i = 0 then v 0 else if i > last then v last else linear s (i - 1) k p
  | Quadratic ->
      if i = 0 then v 0
      else if i > last then v last
      else if last = 1 then linear s (i - 1) k p
      else if i > 1 then quadratic s (i - 1) k p
      else quadratic s i k p
  | Natural -> if i = 0 then v 0 else if i > last then v last else natural s (i - 1) k p
  | Cubic ->
      if last = 1 then (v 0 +. v 1) /. 2.0
      else if i < 2 then v 1
      else if i >= last then v (last - 1)
      else catmull_rom s (i - 1) k p

let eval s p =
  let last = Array.length s.times - 1 in
  if last = 0 then Array.sub s.values.(0) 0 s.terms
  else
    let i = segment s.times (last + 1) p in
    Array.init s.terms (fun k -> term s last i k p)
