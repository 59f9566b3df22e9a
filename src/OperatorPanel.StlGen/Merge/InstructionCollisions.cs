using OperatorPanel.Core.Addressing;
using OperatorPanel.Stl;
using OperatorPanel.StlGen.Diagnostics;

namespace OperatorPanel.StlGen.Merge;

/// <summary>
/// Walks every instruction of the user's program and reports what collides with the handler: its interrupt events and
/// port, writes to the port's special memory and SMB34, V bytes in its footprint; and warns about what the text alone
/// cannot show (indirect accesses, counts that are not constants, symbols).
/// </summary>
internal sealed class InstructionCollisions(AwlProgram user, HandlerFootprint handler, int portCount, int vBytes)
{
    private readonly List<MergeDiagnostic> _found = [];
    private readonly List<OperandUse> _vOverlaps = [];
    private readonly HashSet<int> _touchedVBytes = [];

    public IReadOnlyList<MergeDiagnostic> Find()
    {
        foreach (var instruction in user.Blocks.SelectMany(b => b.Instructions))
        {
            CheckEvents(instruction);
            CheckPort(instruction);
            CheckInterruptsDisabled(instruction);
            foreach (var use in InstructionOperands.Uses(instruction, user))
            {
                CheckOperand(use);
            }
        }

        var free = FreeBufferStart() is { } start ? $" (VB{start}-VB{start + handler.VBytes - 1} is not used by the user's program)" : string.Empty;
        foreach (var use in _vOverlaps)
        {
            Error(StlDiagnostics.VMemoryOverlap, use.Line, $"{use.Describe("VB")} overlaps the handler's {handler.VRange}; move the handler with --buffer VBn{free}");
        }

        return _found;
    }

    /// <summary>The highest even start where the handler's bytes touch nothing the user's program is seen to use.</summary>
    private int? FreeBufferStart()
    {
        for (var start = (vBytes - handler.VBytes) & ~1; start >= 0; start -= 2)
        {
            if (!Enumerable.Range(start, handler.VBytes).Any(_touchedVBytes.Contains))
            {
                return start;
            }
        }

        return null;
    }

    private void CheckEvents(AwlInstruction instruction)
    {
        // CEVNT clears the event's queued interrupts (no page found, [U]: docs/stl-instructions.md lists it unsourced);
        // on the handler's events it would lose a request or a transmit-complete, as DTCH loses them all.
        var eventIndex = instruction.Mnemonic switch { "ATCH" => 1, "DTCH" or "CEVNT" => 0, _ => -1 };
        if (eventIndex < 0 || !TryConstant(instruction, eventIndex, out var number))
        {
            return;
        }

        var verb = instruction.Mnemonic switch { "ATCH" => "attaches", "DTCH" => "detaches", _ => "clears the queued interrupts of" };
        if (handler.Events.Contains((int)number))
        {
            var advice = number == 10
                ? "move the user's routine to timed interrupt 1 (event 11, interval SMB35)"
                : OtherPort("the handler cannot share this port's events");
            Error(StlDiagnostics.EventInUse, instruction.Line, $"{instruction.Mnemonic} {verb} event {number} ({handler.EventPurpose((int)number)}), which the handler uses; {advice}");
        }
        else if (number == handler.ReceiveCharacterEvent && instruction.Mnemonic == "ATCH")
        {
            Error(StlDiagnostics.PortInUse, instruction.Line, $"ATCH attaches event {number} (receive character on port {handler.Port}): the user's program runs Freeport on the handler's port; {OtherPort("the panel needs a port of its own")}");
        }
    }

    private void CheckPort(AwlInstruction instruction)
    {
        // NETR/NETW run only on a port in PPI master mode (seed 002 Table C-11, SMB30/SMB130 mm = 10): on the handler's
        // port they would need the port taken out of Freeport, as XMT/RCV would take its wire.
        if (instruction.Mnemonic is "RCV" or "XMT" or "NETR" or "NETW" && TryConstant(instruction, 1, out var port) && port == handler.Port)
        {
            Error(StlDiagnostics.PortInUse, instruction.Line, $"{instruction.Mnemonic} uses port {port}, the handler's port; {OtherPort("the panel needs a port of its own")}");
        }
    }

    /// <summary>
    /// DISI holds back every interrupt, the handler's receive and transmit events too, until ENI: a program may do so
    /// briefly (around a multi-word copy) and the handler then answers late, or never when ENI does not follow. The text
    /// alone cannot tell which, so a warning naming the line, not a refusal.
    /// </summary>
    private void CheckInterruptsDisabled(AwlInstruction instruction)
    {
        if (instruction.Mnemonic == "DISI")
        {
            Warning(StlDiagnostics.InterruptsDisabled, instruction.Line, $"DISI holds back the handler's interrupts (events {string.Join(", ", handler.Events)}) until the next ENI: the handler answers the panel only after it, or never if no ENI follows; keep the DISI-ENI stretch short");
        }
    }

    private void CheckOperand(OperandUse use)
    {
        var operand = use.Operand;
        switch (operand.Kind)
        {
            case AwlOperandKind.Indirect:
                Warning(StlDiagnostics.IndirectAccessUnchecked, use.Line, $"{operand.Text}: an indirect access cannot be checked against the handler's {handler.VRange} without running the program; make sure the pointer stays outside it");
                break;
            case AwlOperandKind.Symbol when !IsBlockOperand(use):
                Warning(StlDiagnostics.SymbolUnchecked, use.Line, $"{operand.Text}: a symbol's address is not in the exported text, so it is not checked; export with absolute addresses or check it against {handler.VRange} yourself");
                return;
            case AwlOperandKind.Address or AwlOperandKind.Pointer:
                break;
            case AwlOperandKind.Constant or AwlOperandKind.Local or AwlOperandKind.Symbol:
                return;
        }

        if (use.CountUnknown)
        {
            Warning(StlDiagnostics.BlockLengthUnchecked, use.Line, $"{use.Instruction.Mnemonic} {operand.Text}: the count is not a constant, so only the first element is checked against the handler's {handler.VRange}");
        }

        if (operand.Area == MemoryArea.V)
        {
            CheckV(use);
        }
        else if (operand.Area == MemoryArea.SM && use.Written)
        {
            CheckSpecialMemory(use);
        }
    }

    private void CheckV(OperandUse use)
    {
        var (first, last) = use.Bytes;
        for (var b = first; b <= last && b < first + 65536; b++)
        {
            _touchedVBytes.Add(b);
        }

        if (first <= handler.LastVByte && last >= handler.FirstVByte)
        {
            _vOverlaps.Add(use);
        }
    }

    private void CheckSpecialMemory(OperandUse use)
    {
        var (first, last) = use.Bytes;
        bool Covers(int from, int to) => first <= to && last >= from;
        if (Covers(handler.PortControlByte, handler.PortControlByte) || Covers(handler.FirstReceiveByte, handler.LastReceiveByte))
        {
            Error(StlDiagnostics.PortControlWritten, use.Line, $"{use.Instruction.Mnemonic} writes {use.Describe("SMB")}, port {handler.Port}'s mode or receive set-up (SMB{handler.PortControlByte}, SMB{handler.FirstReceiveByte}-SMB{handler.LastReceiveByte}), which the handler owns; remove the write or {OtherPort("the panel needs the port to itself")}");
        }

        if (handler.UsesTimedInterrupt && Covers(HandlerFootprint.ReplyDelayByte, HandlerFootprint.ReplyDelayByte))
        {
            Error(StlDiagnostics.ReplyDelayIntervalWritten, use.Line, $"{use.Instruction.Mnemonic} writes {use.Describe("SMB")}: SMB34 is the handler's reply delay (timed interrupt 0); use timed interrupt 1 (SMB35, event 11) in the user's program");
        }
    }

    private string OtherPort(string otherwise) =>
        portCount > 1 ? $"put the handler on port {1 - handler.Port} with --plc-port {1 - handler.Port}" : otherwise;

    private static bool IsBlockOperand(OperandUse use) =>
        use.Instruction.Mnemonic is "CALL" or "ATCH" && use.Index == 0;

    private static bool TryConstant(AwlInstruction instruction, int index, out long value)
    {
        value = 0;
        if (index >= instruction.Operands.Length || !AwlOperand.TryParse(instruction.Operands[index], out var operand, out _)
            || operand.Kind != AwlOperandKind.Constant || operand.ConstantKind != AwlConstantKind.Integer)
        {
            return false;
        }

        value = operand.Integer;
        return true;
    }

    private void Error(string id, int line, string message) => _found.Add(new MergeDiagnostic(id, MergeSeverity.Error, line, message));

    private void Warning(string id, int line, string message) => _found.Add(new MergeDiagnostic(id, MergeSeverity.Warning, line, message));
}
