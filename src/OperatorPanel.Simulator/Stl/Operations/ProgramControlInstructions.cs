using OperatorPanel.Simulator.Stl.Execution;

namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>
/// Loops, jumps, calls, returns, END, STOP, WDR and sequence control relays. The loader links the targets: FOR's op.N
/// is past its NEXT, NEXT's op.N the first instruction of the body; JMP's op.N its LBL; LSCR's op.N past its SCRE,
/// CSCRE's op.N the SCRE. SCR (A5E00307987-04 chapter 6, "Sequence Control Relay (SCR) Instructions"): LSCR S_bit
/// loads the S bit onto the logic stack and, when it is 0, skips the segment to its SCRE; SCRT S_bit sets the
/// referenced S bit and resets the S bit of the active segment; CSCRE ends the segment here; SCRE marks its end.
/// </summary>
internal static class ProgramControlInstructions
{
    /// <summary>FOR INDX, INIT, FINAL: the loop runs while INDX &lt;= FINAL; INIT &gt; FINAL skips it.</summary>
    public static void For(StlMachine m, StlOp op)
    {
        var init = m.Read(op.B!, 2);
        m.Write(op.A!, 2, init);
        if ((short)init > (short)m.Read(op.C!, 2))
        {
            m.Calls.Jump(op.N);
        }
    }

    /// <summary>FOR without power flow skips its loop.</summary>
    public static long SkipLoop(StlMachine m, StlOp op)
    {
        m.Calls.Jump(op.N);
        return StlTiming.WithoutPowerFlow;
    }

    /// <summary>NEXT: INDX + 1, back to the body while INDX &lt;= FINAL (NEXT carries its FOR's INDX and FINAL).</summary>
    public static void Next(StlMachine m, StlOp op)
    {
        var index = (short)(m.Read(op.A!, 2) + 1);
        m.Write(op.A!, 2, (ushort)index);
        if (index <= (short)m.Read(op.C!, 2))
        {
            m.Calls.Jump(op.N);
        }
    }

    public static void Jump(StlMachine m, StlOp op) => m.Calls.Jump(op.N);

    /// <summary>
    /// A JMP not taken costs its full time, not the 1 us of a box without power flow: the interpreter has charged it so
    /// since it began (the generated handler's figures rest on it); no source says either way.
    /// </summary>
    public static long JumpNotTaken(StlMachine m, StlOp op) => op.Cost;

    public static void Call(StlMachine m, StlOp op) => m.Call(op, m.Blocks[op.Target]);

    /// <summary>RET, CRET, RETI, CRETI.</summary>
    public static void Return(StlMachine m, StlOp op) => m.Return();

    /// <summary>END, MEND.</summary>
    public static void EndMain(StlMachine m, StlOp op) => m.EndMain();

    /// <summary>STOP: the scan ends first (A5E00307987-04, "STOP" instruction).</summary>
    public static void Stop(StlMachine m, StlOp op) =>
        m.StopRequest ??= new StlFault("Stop", "the program executed STOP", m.Calls.BlockName, op.Line);

    /// <summary>WDR: the scan watchdog counts from now.</summary>
    public static void ResetWatchdog(StlMachine m, StlOp op) => m.WatchdogFrom = m.Time.Now;

    public static void LoadScr(StlMachine m, StlOp op)
    {
        var active = m.ReadBit(op.A!);
        m.Logic.Bits = active ? 1u : 0u;
        m.ActiveScr = op.A;
        if (!active)
        {
            m.Calls.Jump(op.N);
        }
    }

    public static void TransitionScr(StlMachine m, StlOp op)
    {
        m.WriteBit(op.A!, true);
        if (m.ActiveScr is { } active && !(active.Offset == op.A!.Offset && active.Bit == op.A.Bit))
        {
            m.WriteBit(active, false);
        }
    }

    public static void EndScr(StlMachine m, StlOp op) => m.ActiveScr = null;

    public static void ConditionalEndScr(StlMachine m, StlOp op) => m.Calls.Jump(op.N);
}
