namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>
/// The running blocks: OB1, the subroutines it called, and an interrupt routine with its subroutines on top. Each level
/// has its own 64 bytes of L, <see cref="LBase"/> being the running level's. Subroutine nesting: 8 levels from the main
/// program, 4 from an interrupt routine ("Executing the user program" in the newer system manuals; the 1998 C233-01
/// manual allowed only one level from an interrupt routine, a limit the generated handler never reaches: it calls
/// nothing from its routines).
/// </summary>
internal sealed class StlCallStack
{
    public const int MainNesting = 8;
    public const int InterruptNesting = 4;

    /// <summary>OB1 and its 8 levels, an interrupt routine and its 4.</summary>
    public const int Levels = MainNesting + InterruptNesting + 2;

    /// <summary>Where an interrupt routine's L starts: above every level the main program can reach.</summary>
    public const int InterruptLBase = (MainNesting + 1) * StlMachine.LBytes;

    private readonly StlFrame[] _frames = new StlFrame[Levels];

    /// <summary>The running level; -1 when no block runs (between scans).</summary>
    public int Depth { get; private set; } = -1;

    /// <summary>The level of the running interrupt routine; -1 when none runs.</summary>
    public int InterruptBase { get; set; } = -1;

    /// <summary>The running level's first byte in L memory.</summary>
    public int LBase { get; set; }

    public bool IsEmpty => Depth < 0;

    public ref StlFrame Current => ref _frames[Depth];

    /// <summary>The subroutine levels in use below the running OB1 or interrupt routine.</summary>
    public int Nesting => InterruptBase >= 0 ? Depth - InterruptBase : Depth;

    public int NestingLimit => InterruptBase >= 0 ? InterruptNesting : MainNesting;

    /// <summary>Where a fault happened: the running block, or the last one that ran.</summary>
    public string BlockName => _frames[Math.Max(Depth, 0)].Block?.Name ?? "?";

    public void Push(StlBlock block, int lBase, StlOp? call, uint savedStack)
    {
        Depth++;
        _frames[Depth] = new StlFrame { Block = block, Pc = 0, SavedStack = savedStack, LBase = lBase, Call = call };
        LBase = lBase;
    }

    /// <summary>Leaves the running level; <see cref="LBase"/> is the caller's again (0 when none is left).</summary>
    public StlFrame Pop()
    {
        var frame = _frames[Depth];
        Depth--;
        LBase = Depth >= 0 ? _frames[Depth].LBase : 0;
        return frame;
    }

    /// <summary>END/MEND or STOP: every level is left at once.</summary>
    public void Clear() => Depth = -1;

    public void Jump(int pc) => _frames[Depth].Pc = pc;

    /// <summary>The .awl line the running main program goes on at; 0 outside OB1 and its subroutines.</summary>
    public int NextLine()
    {
        if (Depth < 0)
        {
            return 0;
        }

        var frame = _frames[Depth];
        return frame.Pc < frame.Block.Ops.Length ? frame.Block.Ops[frame.Pc].Line : 0;
    }
}
