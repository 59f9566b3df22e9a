using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Stl.Operations;
using OperatorPanel.Stl;
using OperatorPanel.Stl.Instructions;

namespace OperatorPanel.Simulator.Stl;

/// <summary>Compiles the instructions of one block into ops: operands resolved, jumps and FOR/NEXT pairs linked, costs set.</summary>
internal sealed class StlBlockCompiler(
    CpuProfile cpu, Dictionary<string, StlBlock> blocks, List<AwlDiagnostic> diagnostics, List<AwlDiagnostic> warnings, StlLoadOptions options)
{
    private readonly StlOperandResolver _resolver = new(cpu);
    private readonly StlTimerNumbers _rules = new();
    private readonly HashSet<int> _silentEvents = [];

    public int EdgeCount { get; private set; }

    public StlOp[] Compile(StlBlock block, IReadOnlyDictionary<string, (StlLoc Loc, int Bytes, bool IsBit)> locals)
    {
        var ops = new List<StlOp>();
        var labels = new Dictionary<int, int>();
        var forStack = new Stack<StlOp>();
        var segment = new List<StlOp>();
        foreach (var instruction in block.Source.Instructions)
        {
            if (CompileOne(block, instruction, locals) is not { } op)
            {
                continue;
            }

            if (op.Code == StlOpCode.Lbl && !labels.TryAdd(op.N, ops.Count))
            {
                Report(instruction.Line, $"LBL {op.N} appears twice in {block.Name}");
            }
            else if (op.Code == StlOpCode.For)
            {
                forStack.Push(op);
                op.N = ops.Count + 1;
            }
            else if (op.Code == StlOpCode.Next)
            {
                LinkNext(op, forStack, block, ops.Count);
            }
            else if (op.Code is StlOpCode.Lscr or StlOpCode.Cscre or StlOpCode.Scre)
            {
                LinkScr(op, segment, ops.Count);
            }

            ops.Add(op);
        }

        foreach (var open in forStack)
        {
            Report(open.Line, $"FOR without NEXT in {block.Name}");
        }

        if (segment.Count > 0)
        {
            Report(segment[0].Line, $"LSCR without SCRE in {block.Name}");
        }

        foreach (var jump in ops.Where(o => o.Code == StlOpCode.Jmp))
        {
            if (labels.TryGetValue(jump.N, out var target))
            {
                jump.N = target;
            }
            else
            {
                Report(jump.Line, $"JMP {jump.N}: there is no LBL {jump.N} in {block.Name}");
            }
        }

        return [.. ops];
    }

    /// <summary>NEXT jumps back to the body (FOR + 1) and reads INDX and FINAL from its FOR; FOR skips past NEXT.</summary>
    private void LinkNext(StlOp next, Stack<StlOp> forStack, StlBlock block, int index)
    {
        if (!forStack.TryPop(out var loop))
        {
            Report(next.Line, $"NEXT without FOR in {block.Name}");
            return;
        }

        next.A = loop.A;
        next.C = loop.C;
        next.N = loop.N;
        loop.N = index + 1;
    }

    /// <summary>LSCR skips past its SCRE, CSCRE jumps to it; segments do not nest (A5E00307987-04, SCR restrictions).</summary>
    private void LinkScr(StlOp op, List<StlOp> segment, int index)
    {
        if (op.Code == StlOpCode.Lscr && segment.Count > 0)
        {
            Report(op.Line, "LSCR inside an SCR segment: close the segment with SCRE first");
        }
        else if (op.Code != StlOpCode.Lscr && segment.Count == 0)
        {
            Report(op.Line, $"{op.Mnemonic} outside an SCR segment (no LSCR before it)");
        }
        else if (op.Code == StlOpCode.Scre)
        {
            segment[0].N = index + 1;
            foreach (var end in segment.Skip(1))
            {
                end.N = index;
            }

            segment.Clear();
            return;
        }

        segment.Add(op);
    }

    private StlOp? CompileOne(
        StlBlock block, AwlInstruction instruction, IReadOnlyDictionary<string, (StlLoc Loc, int Bytes, bool IsBit)> locals)
    {
        var line = instruction.Line;
        if (!StlOperations.TryGet(instruction.Mnemonic, out var operation) || !StlInstructionTable.TryGet(instruction.Mnemonic, out var spec))
        {
            var why = StlOperations.NotExecuted.TryGetValue(instruction.Mnemonic, out var reason) ? $": {reason}" : string.Empty;
            Report(line, $"{instruction.Mnemonic} is not implemented by the simulator{why}");
            return null;
        }

        if (operation.NotSimulated is { } notSimulated)
        {
            if (options.Strict)
            {
                Report(line, $"{instruction.Mnemonic} is not implemented by the simulator: {notSimulated} (--strict)");
                return null;
            }

            warnings.Add(new AwlDiagnostic(line, $"{instruction.Mnemonic}: {notSimulated}; it does nothing here (--strict refuses it)"));
        }

        var code = operation.Code;
        StlOperandType[] types = [.. spec.Operands.Select(StlOperandTypes.Of)];
        if (!PlacedIn(code, block.Kind))
        {
            Report(line, $"{instruction.Mnemonic} cannot be used in {block.Name} ({block.Source.DefaultName})");
            return null;
        }

        var operands = instruction.Operands;
        if (code == StlOpCode.Call ? operands.Length < 1 : operands.Length != types.Length)
        {
            Report(line, $"{instruction.Mnemonic} takes {types.Length} operand(s), found {operands.Length}");
            return null;
        }

        var op = new StlOp
        {
            Operation = operation,
            Line = line,
            Width = code is StlOpCode.CmpLd or StlOpCode.CmpA or StlOpCode.CmpO or StlOpCode.CmpRLd or StlOpCode.CmpRA or StlOpCode.CmpRO
                ? StlOperandResolver.BytesOf(types[0]) : 0,
        };
        if (op.Width > 0)
        {
            var tail = instruction.Mnemonic[(code is StlOpCode.CmpLd or StlOpCode.CmpRLd ? 3 : 2)..];
            op.N = CompareInstructions.RelationOf(tail)!.Value;
        }
        else if (code == StlOpCode.Fnd)
        {
            op.N = CompareInstructions.RelationOf(instruction.Mnemonic[3..])!.Value;
        }
        else if (code is StlOpCode.Eu or StlOpCode.Ed)
        {
            op.N = EdgeCount++;
        }

        var ok = true;
        var locs = new StlLoc?[3];
        for (var i = 0; i < types.Length; i++)
        {
            ok &= TryOperand(op, i, operands[i], types[i], locals, locs);
        }

        if (code == StlOpCode.Call && ok)
        {
            ok = TryParameters(op, operands, locals);
        }

        (op.A, op.B, op.C) = (locs[0], locs[1], locs[2]);
        ok = ok && _rules.Check(op, Report);
        op.Cost = operation.Time.Nanoseconds + (op.Parameters.Length * StlTiming.PerParameter)
            + (StlTiming.IndirectOperand * (locs.Count(l => l?.Kind == StlLocKind.Indirect)
                + op.Parameters.Count(p => p.Actual.Kind == StlLocKind.Indirect)));
        return ok ? op : null;
    }

    private bool TryOperand(
        StlOp op, int index, string text, StlOperandType type,
        IReadOnlyDictionary<string, (StlLoc Loc, int Bytes, bool IsBit)> locals, StlLoc?[] locs)
    {
        var line = op.Line;
        if (!AwlOperand.TryParse(text, out var operand, out var parseError))
        {
            Report(line, $"{op.Mnemonic}: {parseError}");
            return false;
        }

        switch (type)
        {
            case StlOperandType.Block:
                return TryBlock(op, operand);
            case StlOperandType.Label or StlOperandType.Event or StlOperandType.Port:
                var max = type switch
                {
                    StlOperandType.Label => 255,
                    StlOperandType.Event => 33,
                    _ => cpu.CommunicationPorts - 1,
                };
                if (operand is { Kind: AwlOperandKind.Constant, ConstantKind: AwlConstantKind.Integer } && operand.Integer >= 0 && operand.Integer <= max)
                {
                    op.N = (int)operand.Integer;
                    return op.Code != StlOpCode.Atch || IsRaised(op);
                }

                Report(line, $"{op.Mnemonic}: '{text}' is not a {type.ToString().ToLowerInvariant()} number 0-{max}{(type == StlOperandType.Port ? $" on the {cpu.Name}" : string.Empty)}");
                return false;
            case StlOperandType.DWordIn when operand is { Kind: AwlOperandKind.Address, Area: MemoryArea.HC } && !options.Strict:
                // A high-speed counter's current value (MOVD HC0, VD0): no counter runs here, so it reads 0, as HSC does nothing.
                warnings.Add(new AwlDiagnostic(line, $"{op.Mnemonic}: '{operand.Text}': high-speed counters are not simulated; it reads 0 here (--strict refuses it)"));
                locs[index] = new StlLoc { Kind = StlLocKind.Constant, Value = 0 };
                return true;
            default:
                if (_resolver.TryResolve(operand, type, locals, out var loc, out var error))
                {
                    locs[index] = loc;
                    return true;
                }

                Report(line, $"{op.Mnemonic}: {error}");
                return false;
        }
    }

    /// <summary>
    /// The simulator raises the input edges of I0.0-I0.3 (events 0-7, from changes of the field inputs), the Freeport
    /// events (8, 9, 23-26) and the timed interrupts (10, 11). Event numbers: ML801761 p. 172, Table 6-50
    /// (docs/sources/s7200-facts.md section 5). An ATCH to any other event (high-speed counters, pulse outputs, T32/T96)
    /// is warned about once per event, since the rest of the program runs as it would; strict mode refuses it.
    /// </summary>
    private bool IsRaised(StlOp op)
    {
        if (op.N is (>= 0 and <= 11) or (>= 23 and <= 26))
        {
            return true;
        }

        var name = StlInterruptEvents.Name(op.N);
        if (options.Strict)
        {
            Report(op.Line, $"ATCH: event {op.N} ({name}) never fires in the simulator: it raises the input edges (0-7), the Freeport events (8, 9, 23-26) and the timed interrupts (10, 11) only (--strict)");
            return false;
        }

        if (_silentEvents.Add(op.N))
        {
            warnings.Add(new AwlDiagnostic(op.Line, $"ATCH: event {op.N} ({name}) never fires in the simulator; its routine runs only for the events it can raise (--strict refuses it)"));
        }

        return true;
    }

    private bool TryBlock(StlOp op, AwlOperand operand)
    {
        var wanted = op.Code == StlOpCode.Call ? AwlBlockKind.Subroutine : AwlBlockKind.InterruptRoutine;
        if (blocks.TryGetValue(operand.Text, out var target) && target.Kind == wanted)
        {
            op.Target = target.Index;
            return true;
        }

        Report(op.Line, $"{op.Mnemonic}: '{operand.Text}' is not the name of {(wanted == AwlBlockKind.Subroutine ? "a subroutine" : "an interrupt routine")} in this program");
        return false;
    }

    private bool TryParameters(StlOp op, ImmutableArray<string> operands, IReadOnlyDictionary<string, (StlLoc Loc, int Bytes, bool IsBit)> locals)
    {
        var formals = blocks.Values.First(b => b.Index == op.Target).Formals;
        if (formals.Count != operands.Length - 1)
        {
            Report(op.Line, $"CALL {operands[0]}: {formals.Count} parameter(s) declared, {operands.Length - 1} given");
            return false;
        }

        var parameters = new StlParameter[formals.Count];
        var ok = true;
        var locs = new StlLoc?[1];
        for (var i = 0; i < formals.Count; i++)
        {
            var (formal, bytes, section, isBit) = formals[i];
            var output = section != AwlVariableSection.Input;
            var type = (isBit ? 0 : bytes, output) switch
            {
                (0, false) => StlOperandType.BitIn,
                (0, true) => StlOperandType.BitOut,
                (1, false) => StlOperandType.ByteIn,
                (1, true) => StlOperandType.ByteOut,
                (2, false) => StlOperandType.WordIn,
                (2, true) => StlOperandType.WordOut,
                (_, false) => StlOperandType.DWordIn,
                _ => StlOperandType.DWordOut,
            };
            if (TryOperand(op, 0, operands[i + 1], type, locals, locs))
            {
                parameters[i] = new StlParameter(formal, locs[0]!, isBit ? 0 : bytes, section != AwlVariableSection.Output, output);
            }
            else
            {
                ok = false;
            }
        }

        op.Parameters = parameters;
        return ok;
    }

    /// <summary>RET/CRET belong in subroutines, RETI/CRETI in interrupt routines, END/MEND in OB1 (Micro/WIN's rules).</summary>
    private static bool PlacedIn(StlOpCode code, AwlBlockKind kind) => code switch
    {
        StlOpCode.Ret or StlOpCode.Cret => kind == AwlBlockKind.Subroutine,
        StlOpCode.Reti or StlOpCode.Creti => kind == AwlBlockKind.InterruptRoutine,
        StlOpCode.End or StlOpCode.Mend => kind == AwlBlockKind.OrganizationBlock,
        _ => true,
    };

    private void Report(int line, string message) => diagnostics.Add(new AwlDiagnostic(line, message));
}
