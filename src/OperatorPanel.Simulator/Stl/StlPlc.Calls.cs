namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// CALL and return. A call saves the logic stack and starts the subroutine with top of stack 1 (System Manual, CALL);
/// parameters are copied into the callee's 64 bytes of L (IN, IN_OUT) and back to the caller (IN_OUT, OUT).
/// </summary>
public sealed partial class StlPlc
{
    private void Call(StlOp op)
    {
        var nesting = _interruptBase >= 0 ? _depth - _interruptBase : _depth;
        var limit = _interruptBase >= 0 ? InterruptNesting : MainNesting;
        if (nesting >= limit)
        {
            Failed("NestingDepth", $"more than {limit} subroutine levels");
            return;
        }

        var callerBase = _lBase;
        var calleeBase = callerBase + LBytes;
        foreach (var parameter in op.Parameters)
        {
            if (parameter.In)
            {
                CopyParameter(parameter.Actual, callerBase, parameter.Formal, calleeBase, parameter.Bytes);
            }
        }

        Push(_program.Blocks[op.Target], calleeBase, op);
    }

    private void Push(StlBlock block, int lBase, StlOp? call)
    {
        _depth++;
        _frames[_depth] = new StlFrame { Block = block, Pc = 0, SavedStack = _stack, LBase = lBase, Call = call };
        _lBase = lBase;
        _stack = 1;
    }

    /// <summary>Leaves the running block: OUT and IN_OUT copied back, the caller's logic stack restored.</summary>
    private void Return()
    {
        var frame = _frames[_depth];
        _depth--;
        var callerBase = _depth >= 0 ? _frames[_depth].LBase : 0;
        foreach (var parameter in frame.Call?.Parameters ?? [])
        {
            if (parameter.Out)
            {
                CopyParameter(parameter.Formal, frame.LBase, parameter.Actual, callerBase, parameter.Bytes);
            }
        }

        _lBase = callerBase;
        _stack = frame.SavedStack;
        if (_depth < _interruptBase)
        {
            FinishInterrupt();
        }
        else if (_depth < 0)
        {
            EndScan();
        }
    }

    /// <summary>
    /// Copies one parameter (a bit when <paramref name="bytes"/> is 0) between two call levels: L operands are relative to
    /// the level's base, so the base is switched between the read and the write. Leaves the base at <paramref name="toBase"/>.
    /// </summary>
    private void CopyParameter(StlLoc from, int fromBase, StlLoc to, int toBase, int bytes)
    {
        _lBase = fromBase;
        if (bytes == 0)
        {
            var bit = ReadBit(from);
            _lBase = toBase;
            WriteBit(to, bit);
        }
        else
        {
            var value = Read(from, bytes);
            _lBase = toBase;
            Write(to, bytes, value);
        }
    }

    /// <summary>END / MEND: the main program ends for this scan.</summary>
    private void EndMain()
    {
        while (_depth >= 0)
        {
            _depth--;
        }

        EndScan();
    }
}
