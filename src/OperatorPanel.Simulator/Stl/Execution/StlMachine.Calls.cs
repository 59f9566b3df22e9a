namespace OperatorPanel.Simulator.Stl.Execution;

/// <summary>
/// Entering and leaving blocks. A call saves the logic stack and starts the subroutine with top of stack 1 (System
/// Manual, CALL); parameters are copied into the callee's 64 bytes of L (IN, IN_OUT) and back to the caller (IN_OUT,
/// OUT).
/// </summary>
internal sealed partial class StlMachine
{
    /// <summary>Starts <paramref name="block"/> on a new level with its L at <paramref name="lBase"/> and top of stack 1.</summary>
    public void Enter(StlBlock block, int lBase, StlOp? call = null)
    {
        Calls.Push(block, lBase, call, Logic.Bits);
        Logic.Bits = 1;
    }

    /// <summary>CALL: IN and IN_OUT copied into the callee's L; more levels than the CPU allows is a fatal error.</summary>
    public void Call(StlOp op, StlBlock target)
    {
        if (Calls.Nesting >= Calls.NestingLimit)
        {
            Fail("NestingDepth", $"more than {Calls.NestingLimit} subroutine levels");
            return;
        }

        var callerBase = Calls.LBase;
        var calleeBase = callerBase + LBytes;
        foreach (var parameter in op.Parameters)
        {
            if (parameter.In)
            {
                CopyParameter(parameter.Actual, callerBase, parameter.Formal, calleeBase, parameter.Bytes);
            }
        }

        Enter(target, calleeBase, op);
    }

    /// <summary>Leaves the running block: OUT and IN_OUT copied back, the caller's logic stack restored.</summary>
    public void Return()
    {
        var frame = Calls.Pop();
        var callerBase = Calls.LBase;
        foreach (var parameter in frame.Call?.Parameters ?? [])
        {
            if (parameter.Out)
            {
                CopyParameter(parameter.Formal, frame.LBase, parameter.Actual, callerBase, parameter.Bytes);
            }
        }

        Calls.LBase = callerBase;
        Logic.Bits = frame.SavedStack;
        if (Calls.Depth < Calls.InterruptBase)
        {
            InterruptEnded?.Invoke();
        }
        else if (Calls.IsEmpty)
        {
            MainEnded?.Invoke();
        }
    }

    /// <summary>END / MEND: the main program ends for this scan.</summary>
    public void EndMain()
    {
        Calls.Clear();
        MainEnded?.Invoke();
    }

    /// <summary>
    /// Copies one parameter (a bit when <paramref name="bytes"/> is 0) between two call levels: L operands are relative to
    /// the level's base, so the base is switched between the read and the write. Leaves the base at <paramref name="toBase"/>.
    /// </summary>
    private void CopyParameter(StlLoc from, int fromBase, StlLoc to, int toBase, int bytes)
    {
        Calls.LBase = fromBase;
        if (bytes == 0)
        {
            var bit = ReadBit(from);
            Calls.LBase = toBase;
            WriteBit(to, bit);
        }
        else
        {
            var value = Read(from, bytes);
            Calls.LBase = toBase;
            Write(to, bytes, value);
        }
    }
}
