(** The values of the scene language's [spline { … }] (docs/povray-rules.md §11.5; backend/math/splines.cpp):
    (time, value) entries kept sorted by time, and the value at any time by linear, quadratic,
    Catmull-Rom ([cubic_spline]) or natural cubic interpolation, exactly as POV-Ray 3.7 computes
    it (Get_Spline_Val, same float operations in the same order).

    A value keeps POV-Ray's five terms per entry, whatever was written: a float [f] is stored as
    ⟨f, f⟩ (Parse_Express promotes it to two terms) and the terms past what an entry wrote are
    those of the entry written before it in the same block (Parse_Spline reads every entry into
    one buffer), 0 for the first (POV-Ray's buffer is not initialised: it held zeros in every
    test). They matter only when the entries do not all have the same
    number of terms: [spline { 0, <1,2,3,4,5> 1, 1 }] has ⟨1, 1, 3, 4, 5⟩ at time 1. *)

(** [linear_spline] (POV-Ray's default), [quadratic_spline], [cubic_spline] (POV-Ray's
    CATMULL_ROM_SPLINE) and [natural_spline]. *)
type kind = Linear | Quadratic | Cubic | Natural

type t
(** An immutable spline: its kind, its entries sorted by time, the number of terms of its values. *)

val make : kind -> (float * float array) list -> t
(** [make kind entries] is the spline of [entries], given in the order they are written as
    (time, value) with values of 1 (a float) to 5 terms, inserted one by one as
    Insert_Spline_Entry does: sorted by time; an entry whose time is already there replaces that
    entry's value, except when that time is the last one's of a spline of two entries or more
    (POV-Ray writes the value past the end, where it is lost: [spline { 0,0 1,1 1,5 }] is 1 at
    time 1), and then also when the time is -1e6 and comes after every time there (the mark of
    the unused slots). Raises [Invalid_argument] for no entries (the reader reports POV-Ray's
    error before) or a value of 0 or more than 5 terms. *)

val add : t -> (float * float array) list -> t
(** [add s entries] is [spline { S … }] with [S] naming [s]: a copy of [s] with [entries]
    inserted as by {!make} (whose buffer of terms starts again from zeros), of as many terms as
    the widest of [s] and [entries]. *)

val terms : t -> int
(** [terms s] is the number of terms of the values of [s] (POV-Ray's Terms): 2 to 5, the widest
    value written, a float counting as two. *)

val kind : t -> kind
(** [kind s] is the interpolation of [s]. *)

val entries : t -> (float * float array) array
(** [entries s] are the entries of [s] in the order POV-Ray keeps them (increasing times), each
    value of [terms s] terms. *)

val with_kind : t -> kind -> t
(** [with_kind s k] is [s] interpolated as [k]: [spline { S cubic_spline }] and the call
    [S(t, cubic_spline)]. *)

val eval : t -> float -> float array
(** [eval s time] is the value of [s] at [time] (Get_Spline_Val), of [terms s] terms. With one
    entry, its value. Up to the first time and from the last on, the first and the last value;
    a [cubic_spline] interpolates only between its second and last but one times and is the
    second value up to the second time, the last but one after the last but one time. With too
    few entries POV-Ray interpolates with what there is: a quadratic spline of two entries is
    linear; a cubic spline of two entries is the mean of their values at every time, of three
    entries its second value; a natural spline of two entries is linear (with its own float
    operations). *)
