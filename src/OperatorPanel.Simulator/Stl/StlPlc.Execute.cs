namespace OperatorPanel.Simulator.Stl;

// Over 150 lines: one switch over every op code reads better than the same dispatch spread over files.

/// <summary>
/// One instruction with S7-200 semantics. The logic stack is 9 bits, top of stack in bit 0. Box instructions run
/// only when the top of stack is 1 and leave it unchanged.
/// </summary>
public sealed partial class StlPlc
{
    private const uint StackMask = 0x1FF;

    /// <summary>ENO of the last box instruction, for AENO: 0 when it had no power flow or met an error condition.</summary>
    private bool _eno;

    private bool Top => (_stack & 1) != 0;

    /// <summary>Executes <paramref name="op"/>; returns its cost in ns.</summary>
    private long Execute(StlOp op)
    {
        switch (op.Code)
        {
            case StlOpCode.Ld: Push(ReadBit(op.A!)); return op.Cost;
            case StlOpCode.Ldn: Push(!ReadBit(op.A!)); return op.Cost;
            case StlOpCode.A: And(ReadBit(op.A!)); return op.Cost;
            case StlOpCode.An: And(!ReadBit(op.A!)); return op.Cost;
            case StlOpCode.O: Or(ReadBit(op.A!)); return op.Cost;
            case StlOpCode.On: Or(!ReadBit(op.A!)); return op.Cost;
            case StlOpCode.Not: _stack ^= 1; return op.Cost;
            case StlOpCode.Eu: Edge(op.N, rising: true); return op.Cost;
            case StlOpCode.Ed: Edge(op.N, rising: false); return op.Cost;
            case StlOpCode.Lps: _stack = ((_stack << 1) | (_stack & 1)) & StackMask; return op.Cost;
            case StlOpCode.Lrd: _stack = (_stack & ~1u) | ((_stack >> 1) & 1); return op.Cost;
            case StlOpCode.Lpp: _stack >>= 1; return op.Cost;
            case StlOpCode.Ald: _stack = (_stack >> 1) & (((_stack & 1) != 0) ? ~0u : ~1u); return op.Cost;
            case StlOpCode.Old: _stack = (_stack >> 1) | (_stack & 1); return op.Cost;
            case StlOpCode.Assign: WriteBit(op.A!, Top); return op.Cost;
            case StlOpCode.Lbl or StlOpCode.Nop: return 0;
            case StlOpCode.Next: Next(op); return op.Cost;
            case StlOpCode.Ret or StlOpCode.Reti: Return(); return op.Cost;
            case StlOpCode.Mend: EndMain(); return op.Cost;
            case StlOpCode.CmpLd: Push(Compare(op)); return op.Cost;
            case StlOpCode.CmpA: And(Compare(op)); return op.Cost;
            case StlOpCode.CmpO: Or(Compare(op)); return op.Cost;
            case StlOpCode.CmpRLd: Push(CompareReal(op)); return op.Cost;
            case StlOpCode.CmpRA: And(CompareReal(op)); return op.Cost;
            case StlOpCode.CmpRO: Or(CompareReal(op)); return op.Cost;
            case StlOpCode.Ton or StlOpCode.Tonr or StlOpCode.Tof: Timer(op); return op.Cost;
            case StlOpCode.Ctu or StlOpCode.Ctd or StlOpCode.Ctud: Counter(op); return op.Cost;
            case StlOpCode.Ldi: Push(ReadPhysicalInput(op.A!)); return op.Cost;
            case StlOpCode.Ldni: Push(!ReadPhysicalInput(op.A!)); return op.Cost;
            case StlOpCode.Ai: And(ReadPhysicalInput(op.A!)); return op.Cost;
            case StlOpCode.Ani: And(!ReadPhysicalInput(op.A!)); return op.Cost;
            case StlOpCode.Oi: Or(ReadPhysicalInput(op.A!)); return op.Cost;
            case StlOpCode.Oni: Or(!ReadPhysicalInput(op.A!)); return op.Cost;
            case StlOpCode.AssignI: WriteImmediate(op.A!, 1, Top); return op.Cost;
            case StlOpCode.Aeno: And(_eno); return op.Cost;
            case StlOpCode.Lds: Push(((_stack >> (int)Read(op.A!, 1)) & 1) != 0); return op.Cost;
            case StlOpCode.Lscr: LoadScr(op); return op.Cost;
            case StlOpCode.Scre: _activeScr = null; return op.Cost;
            default:
                if (!Top)
                {
                    _eno = false;
                    if (op.Code == StlOpCode.For)
                    {
                        _frames[_depth].Pc = op.N;
                    }

                    return op.Code == StlOpCode.Jmp ? op.Cost : StlTiming.WithoutPowerFlow;
                }

                return ExecuteBox(op);
        }
    }

    /// <summary>Instructions that run only with power flow (top of stack 1).</summary>
    private long ExecuteBox(StlOp op)
    {
        _eno = true;
        switch (op.Code)
        {
            case StlOpCode.Set: WriteBits(op.A!, (int)Read(op.B!, 1), true); break;
            case StlOpCode.Reset: WriteBits(op.A!, (int)Read(op.B!, 1), false); break;
            case StlOpCode.MovB: Write(op.B!, 1, Read(op.A!, 1)); break;
            case StlOpCode.MovW: Write(op.B!, 2, Read(op.A!, 2)); break;
            case StlOpCode.MovD: Write(op.B!, 4, Read(op.A!, 4)); break;
            case StlOpCode.Bmb: return BlockMove(op, 1);
            case StlOpCode.Bmw: return BlockMove(op, 2);
            case StlOpCode.Swap:
                var word = Read(op.A!, 2);
                Write(op.A!, 2, ((word & 0xFF) << 8) | (word >> 8));
                break;
            case StlOpCode.Ath: return AsciiToHex(op);
            case StlOpCode.Hta: return HexToAscii(op);
            case StlOpCode.For: For(op); break;
            case StlOpCode.Jmp: _frames[_depth].Pc = op.N; break;
            case StlOpCode.Call: Call(op); break;
            case StlOpCode.Cret or StlOpCode.Creti: Return(); break;
            case StlOpCode.End: EndMain(); break;
            case StlOpCode.Atch: Attach(op.Target, op.N); break;
            case StlOpCode.Dtch: Detach(op.N); break;
            case StlOpCode.Eni: EnableInterrupts(true); break;
            case StlOpCode.Disi: EnableInterrupts(false); break;
            case StlOpCode.Rcv or StlOpCode.Xmt: PortInstruction(op); break;
            case StlOpCode.SetI: WriteImmediate(op.A!, (int)Read(op.B!, 1), true); break;
            case StlOpCode.ResetI: WriteImmediate(op.A!, (int)Read(op.B!, 1), false); break;
            case StlOpCode.Bir: Write(op.B!, 1, InputImage[op.A!.Offset]); break;
            case StlOpCode.Biw: WriteOutputByteImmediate(op.B!, (byte)Read(op.A!, 1)); break;
            case StlOpCode.MovR: Write(op.B!, 4, Read(op.A!, 4)); break;
            case StlOpCode.Bmd: return BlockMove(op, 4);
            case StlOpCode.Scrt: TransitionScr(op); break;
            case StlOpCode.Cscre: _frames[_depth].Pc = op.N; break;
            case StlOpCode.Stop: _stopRequest ??= new StlFault("Stop", "the program executed STOP", _frames[_depth].Block.Name, op.Line); break;
            case StlOpCode.Wdr: _watchdogFrom = _now; break;
            case StlOpCode.Todr: ReadClock(op); break;
            case StlOpCode.Todw: WriteClock(op); break;
            case StlOpCode.Att or StlOpCode.Fifo or StlOpCode.Lifo or StlOpCode.Fnd or StlOpCode.Fill: Table(op); break;
            default: Arithmetic(op); break;
        }

        return op.Cost;
    }

    private void Push(bool value) => _stack = ((_stack << 1) | (value ? 1u : 0u)) & StackMask;

    /// <summary>A (and AI, AENO, compares): the top of the logic stack ANDed with <paramref name="value"/>.</summary>
    private void And(bool value) => _stack &= value ? ~0u : ~1u;

    /// <summary>O (and OI, compares): the top of the logic stack ORed with <paramref name="value"/>.</summary>
    private void Or(bool value) => _stack |= value ? 1u : 0u;

    /// <summary>EU/ED: each instruction remembers the top of stack it saw last scan; the top becomes 1 only on the change.</summary>
    private void Edge(int slot, bool rising)
    {
        var now = Top;
        var fired = rising ? now && !_edges[slot] : !now && _edges[slot];
        _edges[slot] = now;
        _stack = (_stack & ~1u) | (fired ? 1u : 0u);
    }

    /// <summary>Bytes compare unsigned, words and double words signed (/work/briefs/stl-dialect.md, "Compares").</summary>
    private bool Compare(StlOp op)
    {
        long a = Read(op.A!, op.Width);
        long b = Read(op.B!, op.Width);
        if (op.Width == 2)
        {
            (a, b) = ((short)a, (short)b);
        }
        else if (op.Width == 4)
        {
            (a, b) = ((int)a, (int)b);
        }

        return Holds(op.N, a, b);
    }

    /// <summary>A compare's relation (StlInstructionSet: 0 =, 1 &lt;&gt;, 2 &lt;, 3 &lt;=, 4 &gt;, 5 &gt;=); IEEE rules for reals.</summary>
    private static bool Holds<T>(int relation, T a, T b)
        where T : System.Numerics.INumber<T> => relation switch
        {
            0 => a == b,
            1 => a != b,
            2 => a < b,
            3 => a <= b,
            4 => a > b,
            _ => a >= b,
        };

    private long BlockMove(StlOp op, int unit)
    {
        var count = (int)Read(op.C!, 1) * unit;
        if (TrySpan(op.A!, count, out var from, out var fromOffset) && TrySpan(op.B!, count, out var to, out var toOffset))
        {
            Array.Copy(from, fromOffset, to, toOffset, count);
        }

        return op.Cost + (count * StlTiming.PerByte);
    }

    /// <summary>FOR INDX, INIT, FINAL: the loop runs while INDX &lt;= FINAL; INIT &gt; FINAL skips it (op.N is past NEXT).</summary>
    private void For(StlOp op)
    {
        var init = Read(op.B!, 2);
        Write(op.A!, 2, init);
        if ((short)init > (short)Read(op.C!, 2))
        {
            _frames[_depth].Pc = op.N;
        }
    }

    /// <summary>NEXT: INDX + 1, back to the body (op.N) while INDX &lt;= FINAL.</summary>
    private void Next(StlOp op)
    {
        var index = (short)(Read(op.A!, 2) + 1);
        Write(op.A!, 2, (ushort)index);
        if (index <= (short)Read(op.C!, 2))
        {
            _frames[_depth].Pc = op.N;
        }
    }
}
