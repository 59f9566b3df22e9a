namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Table instructions (A5E00307987-04 chapter 6, "Table Instructions"; C79000-G7076-C233-01 p. 9-109, Figure 9-36 for
/// LIFO). ATT, FIFO and LIFO tables start with TL (maximum entries, at most 100) and EC (entry count), then the
/// entries; FND's table starts with EC. ATT on a full table sets SM1.4, FIFO/LIFO on an empty one SM1.5, both with
/// ENO = 0 and nothing moved. FND=/&lt;&gt;/&lt;/&gt; SRC, PATRN, INDX searches from entry INDX and leaves INDX at
/// the first match, or at EC when none matches. FILL IN, OUT, N writes IN into N words from OUT.
/// </summary>
public sealed partial class StlPlc
{
    private const byte TableFull = 0x10;
    private const byte TableEmpty = 0x20;

    private void Table(StlOp op)
    {
        switch (op.Code)
        {
            case StlOpCode.Att: AddToTable(op); break;
            case StlOpCode.Fifo: TakeFromTable(op, first: true); break;
            case StlOpCode.Lifo: TakeFromTable(op, first: false); break;
            case StlOpCode.Fnd: Find(op); break;
            default: Fill(op); break;
        }
    }

    /// <summary>ATT DATA, TBL.</summary>
    private void AddToTable(StlOp op)
    {
        if (!TrySpan(op.B!, 2, out var area, out var offset))
        {
            return;
        }

        var limit = (short)ReadBytes(area, offset, 2);
        var count = (short)ReadBytes(area, offset + 2, 2);
        var full = count >= limit;
        if (!full && TrySpan(op.B!, 4 + ((count + 1) * 2), out _, out _))
        {
            WriteBytes(area, offset + 4 + (count * 2), 2, Read(op.A!, 2));
            WriteBytes(area, offset + 2, 2, (uint)(count + 1));
        }

        SetFlags(TableFull, full ? TableFull : (byte)0);
        _eno = !full;
    }

    /// <summary>FIFO TBL, DATA (oldest entry, the rest move up) and LIFO TBL, DATA (newest entry).</summary>
    private void TakeFromTable(StlOp op, bool first)
    {
        if (!TrySpan(op.A!, 4, out var area, out var offset))
        {
            return;
        }

        var count = (short)ReadBytes(area, offset + 2, 2);
        var empty = count <= 0;
        if (!empty && TrySpan(op.A!, 4 + (count * 2), out _, out _))
        {
            var entries = offset + 4;
            Write(op.B!, 2, ReadBytes(area, first ? entries : entries + ((count - 1) * 2), 2));
            if (first)
            {
                Array.Copy(area, entries + 2, area, entries, (count - 1) * 2);
            }

            WriteBytes(area, offset + 2, 2, (uint)(count - 1));
        }

        SetFlags(TableEmpty, empty ? TableEmpty : (byte)0);
        _eno = !empty;
    }

    private void Find(StlOp op)
    {
        if (!TrySpan(op.A!, 2, out var area, out var offset))
        {
            return;
        }

        var count = (short)ReadBytes(area, offset, 2);
        var pattern = (short)Read(op.B!, 2);
        for (var index = Math.Max((short)0, (short)Read(op.C!, 2)); index < count && TrySpan(op.A!, 4 + (index * 2), out _, out _); index++)
        {
            var entry = (short)ReadBytes(area, offset + 2 + (index * 2), 2);
            if (op.N switch { 0 => entry == pattern, 1 => entry != pattern, 2 => entry < pattern, _ => entry > pattern })
            {
                Write(op.C!, 2, (ushort)index);
                return;
            }
        }

        Write(op.C!, 2, (ushort)Math.Max((short)0, count));
    }

    /// <summary>FILL IN, OUT, N.</summary>
    private void Fill(StlOp op)
    {
        var words = (int)Read(op.C!, 1);
        if (TrySpan(op.B!, words * 2, out var area, out var offset))
        {
            var value = Read(op.A!, 2);
            for (var i = 0; i < words; i++)
            {
                WriteBytes(area, offset + (i * 2), 2, value);
            }
        }
    }
}
