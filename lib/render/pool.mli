(** Running independent tasks in worker processes (fork), without copying or compacting the
    parent's heap first. *)

exception Worker_failed of string
(** A worker died or raised; the message says how. *)

exception Cannot_write of string
(** The workers' results, which go through files in the temporary directory ([TMPDIR]), could
    not be written there (a full disk): the directory and the system's reason, in plain words
    ("/tmp: No space left on device"). *)

val map : workers:int -> ('a -> 'b) -> 'a list -> 'b list
(** [map ~workers f xs] is [List.map f xs], computed by up to [workers] processes that take the
    next task as they finish one. With one worker (or one task) it runs in this process. Results
    come back by [Marshal], so they must not contain functions. When [map] raises (an
    [Interrupt.Interrupted] among others) it has killed and reaped its workers first; a worker
    whose parent was killed exits within half a second. Workers ignore SIGINT (the parent
    decides) and write nothing but their results and stderr.
    @raise Cannot_write when the workers' results cannot be written. *)

val iter : workers:int -> ('a -> 'b) -> 'a list -> (int -> 'b -> unit) -> unit
(** [iter ~workers f xs consume] computes [f] of each element of [xs] as [map] does and hands
    each result with its element's index to [consume], in this process, as it is read back, in no
    particular order; none is kept, so the results of a large task list need not fit in memory at
    once. With one worker [consume] takes each result before the next is computed, so [f] may
    return a buffer it reuses. *)
