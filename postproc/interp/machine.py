"""The interpreter: executes a stored program and yields the concrete blocks it runs, in order.

A concrete block is what the controller would run: every expression word evaluated and spelled as a
number by the reading dialect (``Host.spell_evaluated``), vacant words omitted, control statements and
assignments gone. It flows on into the dialect's block syntax like a block of a straight program.

Rules (each a choice where the contract is silent, and tested):
- In one block, word values and assignment right-hand sides are read first, then the assignments are
  made, then the concrete block runs, then the block's control statement (a call, jump or loop test)
  is evaluated with the new values. A control block's other words (``G01 X10. M98 P2000``) run first.
- ``Limits.loop_iterations`` bounds the total of loop iterations, jumps taken, returns to a start and
  calls (every repetition counts), so neither a loop nor a wide recursion can run forever;
  ``Limits.call_depth`` bounds nesting. ``Limits.repeated_work`` bounds the work: the blocks run again
  (the first run of each block is free) and the moves their expansions make downstream (counted in
  ``Context.moves_made``, charged when the interpreter resumes after such a block), so a loop ends within
  seconds whatever its iteration count or its body, and the error names the repetition (loop, jump,
  return or call) that ran last.
- A runtime error (division by zero, a missing label...) is reported at its block, with the call
  stack, and execution stops: what follows would rest on a value that does not exist.
- A modal call (G66) runs after each block that has an axis word, except inside the called macro.
"""

from __future__ import annotations

from typing import Iterator

from .control import (
    ASSIGN, CONTROL, LABEL, GotoLabel, Assign, Break, Call, Case, Continue, Default, Do, DoWhile, Else, ElseIf, EndFor, EndIf,
    EndRepeat, EndSwitch, EndWhile, For, Goto, If, IfThen, ModalCall, ModalCallCancel, Repeat, Return, SubEnd,
    SubStart, Switch, Until, While,
)
from ..errors import PostprocError, ProgramError
from .evaluation import evaluate, evaluate_number
from ..ir.expr import EvalError, Expr, Value
from .evaluation import var_key
from ..ir import Block, Comments
from ..ir.source_map import CallSite, ExecutedBlock, Origin
from .frame import Frame
from .host import Interrupt, Reporter
from .store import Program, source_text
from .structure import flow_overflow
from .run_state import RunState, is_number
from .variables import ProgramAlarm

NON_WORD_SECTIONS = frozenset((CONTROL, ASSIGN, LABEL))


class Interpreter(RunState):
    """Runs one program store. ``run()`` yields the concrete blocks; ``annotate`` adds a comment block
    before each call, loop iteration and jump taken (for a flattened program's reader)."""

    # -- running ---------------------------------------------------------------------------------
    def run(self, start: int = 0) -> Iterator[Block]:
        main = self.store.main
        self.frames = [Frame(main, start, main.main_end, None, False, None, 1, 1, {}, False, None)]
        try:
            yield from self._loop()
        except Interrupt:
            return

    def call_apart(self, name: str, block: Block, report: Reporter) -> Iterator[Block]:
        """Run subprogram ``name`` as a call made by ``block`` where this run stands (suspended at a block it
        yielded), in a run of its own: the same store and variables, the call a new level, the bounds fresh,
        no annotation and no modal call; its errors go to ``report`` and end it. The blocks it yields are the
        call's concrete blocks. LinuxCNC runs a G70-G72 cycle's profile so: its interpreter reads
        ``O<q> CALL``, then block after block through the o-word control flow and the parameter assignments
        until the call level is back to the cycle's, taking each block's moves into the profile [V: LinuxCNC
        ``src/emc/rs274ngc/interp_g7x.cc`` ``convert_g7x``, 2.9.0 to master]."""
        nested = Interpreter(self.store, self.host, self.vars, self.limits, report, rules=self.rules,
                             counts=self.counts)
        caller = self.frames[-1] if self.frames else Frame(self.store.main, 0, 0, None, False, None, 1, 1, {},
                                                           False, None)
        base = Frame(caller.program, caller.pc, caller.pc, caller.origin, False, None, 1, 1, {}, False, None)
        nested.frames = [base]  # runs nothing of its own: the run ends when the call returns to it
        try:
            try:
                yield from nested._enter(base, block, name, {}, 1, True, modal=False)
            except PostprocError as err:
                nested._fail(err, base, block, 1)
            yield from nested._loop()
        except Interrupt:
            return
        finally:  # stopped inside the call (an error, or the reader of its blocks done): its levels are left
            while len(nested.frames) > 1:
                self.vars.leave(nested.frames.pop().new_level, None)

    def _loop(self) -> Iterator[Block]:
        frames = self.frames
        while frames and not self.ended:
            frame = frames[-1]
            if frame.pc >= frame.end:
                if len(frames) == 1:
                    return
                if frame.needs_return:
                    last = frame.program.blocks[frame.end - 1]
                    label = frame.site.label if frame.site is not None else "the subprogram"
                    self._fail(ProgramError(f"subprogram {label} runs to the end of the file without returning"),
                               frame, last, 1)
                self._return(frame, frame.program.blocks[frame.end - 1] if frame.end else None, None, None)
                continue
            pc = frame.pc
            program = frame.program
            block = program.blocks[pc]
            made = self.counts.moves_made
            if made != self.moves_seen:
                if self.again:
                    self.work -= made - self.moves_seen
                self.moves_seen = made
            self.again = again = program.ran[pc] == 1
            if again:
                self.work -= 1
            else:
                program.ran[pc] = 1
            if self.work < 0:
                self._out_of_work(frame, block)
            try:
                yield from self._step(frame, block)
            except ProgramAlarm as err:
                comments = block.sections.get("Comments")
                err.with_message(comments.texts if isinstance(comments, Comments) else [])
                self._fail(err, frame, block, (block.text or "").find(err.word) + 1 or 1)
            except EvalError as err:
                self._fail(err, frame, block, self._column(block, err))
            except PostprocError as err:
                self._fail(err, frame, block, 1)

    def _step(self, frame: Frame, block: Block) -> Iterator[Block]:
        sections = block.sections
        control = sections.get(CONTROL)
        assign = sections.get(ASSIGN)
        if len(self.frames) > 1 and ("TapeMark" in sections or "ProgramStart" in sections) and control is None:
            frame.pc += 1  # a subprogram's file framing and label are not statements
            return
        if self.skip_refused is not None and "BlockDelete" in sections and (
                control is not None or assign is not None or (self.modal is not None and self._moves(block))):
            raise ProgramError(f"'{source_text(block)}' is under block delete: {self.skip_refused}")
        concrete = self._concrete(frame, block, control is not None or assign is not None)
        if assign is not None:
            self._assign(assign)  # type: ignore[arg-type]
        if concrete is not None:
            yield concrete
            if self.host.is_program_end(concrete):
                self.ended = True
                return
        if control is None:
            frame.pc += 1
            if concrete is not None and self.modal is not None and not frame.modal and self._moves(concrete):
                yield from self._modal_call(frame, block)
            return
        yield from self._control(frame, block, control)

    # -- words and assignments -------------------------------------------------------------------
    def _concrete(self, frame: Frame, block: Block, statement: bool) -> ExecutedBlock | None:
        values = block.values
        words = block.words
        changed = False
        out: list[tuple[str, str]] = []
        if values:
            for letter, text in words:
                up = letter.upper()
                value = values.get(up)
                if isinstance(value, Expr) and not is_number(text):
                    changed = True
                    number = evaluate(value, self.vars)
                    if number is not None:
                        try:
                            out.append((letter, self.host.spell_evaluated(up, number)))
                        except ProgramError as err:
                            err.message = f"{err.message} ({letter}{text})"
                            err.located(self._where(frame, block, self._word_column(block, letter, text)))
                            raise
                    elif self.vacant_word is not None:
                        vacant = ProgramError(f"{letter}{text} is vacant here: {self.vacant_word}")
                        vacant.located(self._where(frame, block, self._word_column(block, letter, text)))
                        raise vacant
                else:
                    out.append((letter, text))
        else:
            out = list(words)
        if statement and all(letter.upper() == self.host.SEQUENCE_LETTER for letter, _ in out):
            return None
        result = ExecutedBlock(block.line, None if changed else block.text, block.eol, out, frame.origin)
        result.canonical = block.canonical and not changed
        if result.canonical:
            result.values = dict(block.values)  # what its words read as (a straight writer compares them)
        for key, section in block.sections.items():
            if key not in NON_WORD_SECTIONS:
                result.sections[key] = section
        return result

    def _assign(self, assign: Assign) -> None:
        """Read every right-hand side, then set the variables in order (LinuxCNC's rule)."""
        vars_ = self.vars
        targets = [(var_key(var, vars_), evaluate(value, vars_)) for var, value in assign.items]
        for key, value in targets:
            vars_.write(key, value)

    def _moves(self, block: Block) -> bool:
        axes = self.host.AXIS_LETTERS
        return any(letter.upper() in axes for letter, _ in block.words)

    # -- control statements ----------------------------------------------------------------------
    def _control(self, frame: Frame, block: Block, control: object) -> Iterator[Block]:
        pos = frame.pc
        program = frame.program
        vars_ = self.vars
        if self.rules.flow_stack is not None and pos in program.flow_entries and not isinstance(control, Call):
            self._flow(frame.flow + program.flow_entries[pos], block)  # (a call's: ``_enter``)
        if isinstance(control, Goto):
            if control.cond is not None and not _true(evaluate(control.cond, vars_)):
                frame.pc += 1
                return
            number = self._integer(control.target, "the jump target")
            target = program.find_sequence(number, pos)
            if target is None and control.fallthrough:
                frame.pc += 1
                return
            if target is None:
                raise ProgramError(self._missing_sequence(program, number, source_text(block)))
            self._within(frame, target, block)
            self._spend(block, "jump", back=target <= pos)
            if target <= pos:
                self._endless(frame, len(program.blocks) + pos, block, "jump")
            yield from self._note(frame, block, "jump")
            frame.pc = target
        elif isinstance(control, GotoLabel):
            if control.cond is not None and not _true(evaluate(control.cond, vars_)):
                frame.pc += 1
                return
            found = program.find_label(control.label, pos)
            if found is None and control.fallthrough:
                frame.pc += 1
                return
            if found is None:
                raise ProgramError(f"'{source_text(block)}': no block labelled {control.label} in {program.file}")
            self._within(frame, found, block)
            self._spend(block, "jump", back=found <= pos)
            if found <= pos:
                self._endless(frame, len(program.blocks) + pos, block, "jump")
            yield from self._note(frame, block, "jump")
            frame.pc = found
        elif isinstance(control, IfThen):
            if _true(evaluate(control.cond, vars_)):
                self._assign(control.assign)
            frame.pc += 1
        elif isinstance(control, While):
            fresh = frame.back != pos
            if fresh:
                frame.seen.pop(pos, None)  # entered afresh: its earlier runs say nothing of this one
            frame.back = -1
            if _true(evaluate(control.cond, vars_)):
                if fresh:
                    self._fixed(frame, pos, program.pairs[pos], control.cond, block)
                frame.pc += 1
                yield from self._note(frame, block, "iteration")
            else:
                frame.pc = program.pairs[pos] + 1
        elif isinstance(control, EndWhile):
            self._spend(block, "loop")
            head = program.pairs[pos]
            self._endless(frame, head, block, "loop")
            frame.pc = head  # back to the head: its test runs again
            frame.back = head
        elif isinstance(control, Do):
            frame.seen.pop(pos, None)  # entered afresh (its end goes back past it)
            frame.pc += 1
            yield from self._note(frame, block, "iteration")
        elif isinstance(control, DoWhile):
            if _true(evaluate(control.cond, vars_)):
                self._spend(block, "loop")
                head = program.pairs[pos]
                self._fixed(frame, head, pos, control.cond, block)
                self._endless(frame, head, block, "loop")
                frame.pc = head + 1
                yield from self._note(frame, program.blocks[program.pairs[pos]], "iteration")
            else:
                frame.pc += 1
        elif isinstance(control, Repeat):
            count = self._count(control.count, "the repeat count")
            end = program.pairs[pos]
            if count <= 0:
                frame.pc = end + 1
            else:
                frame.repeats[pos] = count
                frame.pc += 1
                yield from self._note(frame, block, "iteration")
        elif isinstance(control, EndRepeat):
            head = program.pairs[pos]
            left = frame.repeats.get(head, 1) - 1
            frame.repeats[head] = left
            if left > 0:
                self._spend(block, "loop")
                frame.pc = head + 1
                yield from self._note(frame, program.blocks[head], "iteration")
            else:
                frame.pc = pos + 1
        elif isinstance(control, For):
            first = evaluate_number(control.start, vars_, "the loop's start")
            last = evaluate_number(control.end, vars_, "the loop's end")
            stride = evaluate_number(control.step, vars_, "the loop's step")
            vars_.write(var_key(control.counter, vars_), first)
            frame.fors[pos] = (last, stride)
            frame.seen.pop(pos, None)  # entered afresh (its end goes back past it)
            if _counting(first, last, stride):
                frame.pc += 1
                yield from self._note(frame, block, "iteration")
            else:
                frame.pc = program.pairs[pos] + 1
        elif isinstance(control, EndFor):
            head = program.pairs[pos]
            loop = program.blocks[head].get(CONTROL)
            last, stride = frame.fors[head]
            key = var_key(loop.counter, vars_)
            counted = evaluate_number(loop.counter, vars_, "the loop's counter") + stride
            vars_.write(key, counted)
            if _counting(counted, last, stride):
                self._spend(block, "loop")
                self._endless(frame, head, block, "loop")
                frame.pc = head + 1
                yield from self._note(frame, program.blocks[head], "iteration")
            else:
                frame.pc = pos + 1
        elif isinstance(control, Until):
            if _true(evaluate(control.cond, vars_)):
                frame.pc += 1
            else:
                self._spend(block, "loop")
                head = program.pairs[pos]
                self._fixed(frame, head, pos, control.cond, block)
                self._endless(frame, head, block, "loop")
                frame.pc = head + 1
                yield from self._note(frame, program.blocks[program.pairs[pos]], "iteration")
        elif isinstance(control, Switch):
            selector = evaluate_number(control.value, vars_, "the switch value")
            chain = program.chains[pos]
            frame.pc = program.pairs[pos] + 1  # no branch taken: after the end
            default = None
            for at in chain[1:]:
                member = program.blocks[at].get(CONTROL)
                if isinstance(member, Default):
                    default = at
                elif abs(evaluate_number(member.value, vars_, "a case value")
                         - selector) < control.tolerance:
                    frame.pc = at + 1
                    break
            else:
                if default is not None:
                    frame.pc = default + 1
        elif isinstance(control, (Case, Default)):
            raise ProgramError(f"'{source_text(block)}' is reached from the branch before it, which does not end "
                               f"with a break (running on into the next branch is not modelled)")
        elif isinstance(control, EndSwitch):
            frame.pc += 1
        elif isinstance(control, Continue):
            head = program.pairs[pos]
            if isinstance(program.blocks[head].get(CONTROL), While):
                self._spend(block, "loop")
                frame.pc = head
            else:
                frame.pc = program.pairs[head]  # the end of a do or repeat loop: its test runs next
        elif isinstance(control, Break):
            frame.pc = program.pairs[program.pairs[pos]] + 1
        elif isinstance(control, If):
            chain = program.chains[pos]
            for at in chain:  # the first branch whose condition holds (or the else) runs
                member = program.blocks[at].get(CONTROL)
                if isinstance(member, EndIf):
                    frame.pc = at
                    break
                if isinstance(member, Else) or _true(evaluate(member.cond, vars_)):
                    frame.pc = at + 1
                    break
        elif isinstance(control, (ElseIf, Else)):
            frame.pc = program.chains[pos][-1]  # the end of a branch that ran: on to the endif
        elif isinstance(control, EndIf):
            frame.pc += 1
        elif isinstance(control, SubStart):
            end = program.pairs[pos]  # a definition met in the flow is skipped, its end run if the rules say
            closing = program.blocks[end].get(CONTROL)
            if self.rules.definition_runs_its_end and isinstance(closing, SubEnd):
                self.vars.returned(None if closing.value is None
                                   else evaluate_number(closing.value, vars_, "a return value"))
            frame.pc = end + 1
        elif isinstance(control, SubEnd):
            value, later = self._returned(control.value)
            self._return(frame, block, value, None, later)
        elif isinstance(control, Return) and len(self.frames) == 1 and self.rules.main_return_refused:
            raise ProgramError(f"'{source_text(block)}' returns from the main program (it ends a subroutine)")
        elif isinstance(control, Return) and len(self.frames) == 1 and self.rules.main_return_words:
            self.ended = True  # the words that end the program run instead
            yield ExecutedBlock(block.line, None, block.eol, list(self.rules.main_return_words), frame.origin)
        elif isinstance(control, Return):
            value, later = self._returned(control.value)
            target = None if control.target is None else self._integer(control.target, "the return target")
            self._return(frame, block, value, target, later)
        elif isinstance(control, Call):
            yield from self._call(frame, block, control)
        elif isinstance(control, ModalCall):
            args = self._args(control.args)
            count = 1 if control.repeat is None else self._count(control.repeat, "the repeat count")
            self.modal = (control, args, count, block)
            frame.pc += 1
        elif isinstance(control, ModalCallCancel):
            self.modal = None
            frame.pc += 1
        else:
            raise ProgramError(f"'{source_text(block)}' cannot be executed ({type(control).__name__})")

    def _flow(self, entry: int, block: Block) -> None:
        """A loop, condition or call that runs holds ``entry`` of the controller's flow stack (its callers'
        entries and its own body's): past the stack, the controller stops. The text's nesting is checked
        where it is read (``Structure``); a sub that calls itself nests deeper only as it runs."""
        limit = self.rules.flow_stack
        if limit is not None and entry > limit:
            raise ProgramError(flow_overflow(block, entry, limit))

    def _note(self, frame: Frame, block: Block, what: str) -> Iterator[Block]:
        if self.annotate:
            yield self._comment(frame, block, what)

    def _comment(self, frame: Frame, block: Block, what: str) -> ExecutedBlock:
        text = source_text(block).replace("(", "[").replace(")", "]")
        note = ExecutedBlock(block.line, None, block.eol or "\n", [], frame.origin)
        note.sections["Comments"] = Comments([f"LINE {block.line}: {text}, {what}"])
        return note

    # -- calls and returns -----------------------------------------------------------------------
    def _call(self, frame: Frame, block: Block, call: Call) -> Iterator[Block]:
        name = self._name(call.name)
        args = self._args(call.args)
        count = 1 if call.repeat is None else self._count(call.repeat, "the repeat count")
        flow = frame.flow + frame.program.flow_entries.get(frame.pc, 0)
        frame.pc += 1
        if count <= 0:
            return
        yield from self._enter(frame, block, name, args, count, call.kind == "macro", modal=False, flow=flow)

    def _modal_call(self, frame: Frame, block: Block) -> Iterator[Block]:
        assert self.modal is not None
        call, args, count, at = self.modal
        yield from self._enter(frame, block, self._name(call.name), dict(args), count, True, modal=True)

    def _enter(self, frame: Frame, block: Block, name: str, args: dict[int, Value], count: int,
               new_level: bool, modal: bool, index: int = 1, flow: int = 0) -> Iterator[Block]:
        label = self.host.program_label(name)
        if self.rules.forward_search:
            found = self._find_forward(frame, block, name, label, new_level)
        else:
            found = self.store.find(name)
        if found is None:
            raise ProgramError(f"subprogram {label} not found (called by '{source_text(block)}')")
        if len(self.frames) > self.limits.call_depth:
            raise ProgramError(f"'{source_text(block)}' exceeds the set-up's bound of {self.limits.call_depth} "
                               f"nested calls (<Limits callDepth=\"{self.limits.call_depth}\"/>)")
        levels = self.rules.call_levels
        if levels is not None and len(self.frames) > levels:
            raise ProgramError(f"'{source_text(block)}' exceeds the controller's bound of {levels} nested calls (it "
                               "refuses a deeper one)")
        self._flow(flow, block)
        self._spend(block, "call")
        program, start, end = found
        caller_file = frame.origin.file if frame.origin is not None else frame.program.file
        site = CallSite(label, caller_file, block.line, index, count)
        stack = (site,) + (frame.origin.stack if frame.origin is not None else ())
        origin = Origin(program.file, stack)
        callee = Frame(program, start, end, origin, new_level, block, index, count, args,
                        modal or frame.modal, site)
        callee.needs_return = self.rules.forward_search and not new_level
        callee.flow = flow
        self.vars.enter(args, new_level)
        self.frames.append(callee)
        yield from self._note(frame, block, f"call {index} of {count}" if count > 1 else "call")

    def _returned(self, expr: Expr | None) -> tuple[Value, Expr | None]:
        """A return's value: evaluated here, in the returning level (None, None: it has none), or, where the
        rules say the controller evaluates it back in the caller (``SubprogramRules.value_in_caller``) and this
        is a call, left to ``_return`` as its expression (``(None, expr)``)."""
        if expr is None:
            return None, None
        if self.rules.value_in_caller and len(self.frames) > 1:
            return None, expr
        return evaluate_number(expr, self.vars, "a return value"), None

    def _return(self, frame: Frame, block: Block | None, value: Value, target: int | None,
                later: Expr | None = None) -> None:
        """Back from ``frame``, returning ``value``, or ``later`` evaluated once the caller's level is back."""
        frames = self.frames
        if len(frames) == 1 and self.called and target is None:
            self.ended = True  # a macro file run on its own returns to its (absent) caller: the run ends
            return
        if len(frames) == 1:  # a return in the main program: back to its start (Fanuc M99)
            assert block is not None
            self._spend(block, "return")
            self._endless(frame, -1 - frame.pc, block, "return")  # (below 0: no while loop's head)
            if target is None:
                frame.pc = 0
                return
            pos = frame.program.find_sequence(target, frame.pc)
            if pos is None:
                raise ProgramError(self._missing_sequence(frame.program, target, source_text(block)))
            frame.pc = pos
            return
        frames.pop()
        self.vars.leave(frame.new_level, value)
        if later is not None:
            self.vars.returned(evaluate_number(later, self.vars, "a return value"))
        caller = frames[-1]
        if frame.index < frame.count and target is None:
            call_block = frame.call_block
            again = Frame(frame.program, frame.start, frame.end, None, frame.new_level, call_block,
                           frame.index + 1, frame.count, frame.args, frame.modal, frame.site)
            assert call_block is not None and frame.site is not None  # set on every called frame
            self._spend(call_block, "call")
            site = CallSite(frame.site.label, frame.site.file, frame.site.line, again.index, frame.count)
            assert frame.origin is not None
            again.origin = Origin(frame.origin.file, (site,) + frame.origin.stack[1:])
            again.site = site
            again.needs_return = frame.needs_return
            again.flow = frame.flow
            self.vars.enter(frame.args, frame.new_level)
            frames.append(again)
            return
        if target is not None:
            assert block is not None
            pos = caller.program.find_sequence(target, caller.pc - 1)
            if pos is None:
                raise ProgramError(self._missing_sequence(caller.program, target, source_text(block)))
            caller.pc = pos

    def _find_forward(self, frame: Frame, block: Block, name: str, label: str,
                      new_level: bool) -> tuple[Program, int, int] | None:
        """LinuxCNC: an ``M98`` finds ``O<n>`` from the call onward (``SubprogramRules``); an o-word call
        finds ``o<n> sub`` in the store, and refuses an ``O<n>``."""
        if new_level:
            found = self.store.find(name)
            if found is not None and found[1] > 0 and "ProgramStart" in found[0].blocks[found[1] - 1].sections:
                raise ProgramError(f"'{source_text(block)}' calls {label}, a numbered subprogram ended by a "
                                   f"return code, which only a subprogram call runs (not an o-word call)")
            return found
        program = frame.program
        key = (program.file, name)
        at = self.found.get(key)
        if at is None:
            blocks = program.blocks
            for pos in range(frame.pc, len(blocks)):
                sections = blocks[pos].sections
                start = sections.get("ProgramStart")
                if start is not None and str(start.number) == name:  # type: ignore[attr-defined]
                    at = pos
                    break
                control = sections.get(CONTROL)
                if isinstance(control, SubStart) and control.name == name:
                    raise ProgramError(f"'{source_text(block)}' calls {label}, an o-word subprogram "
                                       f"(o.. sub), which only an o-word call runs")
            if at is None:
                raise ProgramError(f"'{source_text(block)}': subprogram {label} not found after line {block.line} of "
                                   f"{program.file} (the call looks for it from the call onward)")
            self.found[key] = at
        end = len(program.blocks)
        for pos in range(at + 1, end):
            if "TapeMark" in program.blocks[pos].sections:
                end = pos
                break
        return program, at + 1, end


def _counting(value: float, end: float, step: float) -> bool:
    """A counted loop runs on while its counter has not passed its end (step 0: always)."""
    return value <= end if step > 0.0 else value >= end if step < 0.0 else True


def _true(value: Value) -> bool:
    """A condition holds when its value is a non-zero number (vacant is false)."""
    return value is not None and value != 0.0
