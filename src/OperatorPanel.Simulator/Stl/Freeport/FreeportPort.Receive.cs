namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>RCV and the receiver: characters off the line into SMB2/SM3.0, event 8/25, and the active receive.</summary>
public sealed partial class FreeportPort
{
    private ReceiveMessage? _receive;

    public void Receive(int bufferOffset)
    {
        if (!TryEnterFreeport())
        {
            return;
        }

        var setup = ReceiveSetup.Read(_memory.SM, _registers);
        LastFault = FreeportFault.None;
        if (!setup.Enabled)
        {
            if (_receive is not null)
            {
                EndReceive(ReceiveStatus.UserDisable, _now, _pending);
            }

            return;
        }

        if (_transmission is not null)
        {
            LastFault = FreeportFault.SimultaneousTransmitReceive;
        }
        else if (_receive is not null)
        {
            LastFault = FreeportFault.ReceiveAlreadyActive;
        }
        else if (!setup.IsValid)
        {
            _memory.SM[_registers.Status] = ReceiveStatus.ParameterError;
            LastFault = FreeportFault.ReceiveParameterError;
        }
        else if (bufferOffset < 0 || bufferOffset + setup.MaxCount >= _memory.V.Length)
        {
            LastFault = FreeportFault.BufferOutOfRange;
        }
        else
        {
            _memory.SM[_registers.Status] = 0;
            _receive = new ReceiveMessage(setup, _memory.V, bufferOffset, _now);
        }
    }

    /// <summary>The receiver decodes at the Freeport settings, or at the PPI line while the port speaks PPI.</summary>
    private ReceivedCharacter? PeekCharacter() => _input.Next(!IsFreeport && _ppi is not null ? _ppi.Settings.Line : Line, _readyAt);

    private void TakeCharacter(ReceivedCharacter character, ICollection<StlEvent> raised)
    {
        _readyAt = character.ReadyAt;
        if (!IsFreeport && _ppi is not null)
        {
            TakePpiCharacter(character);
            return;
        }

        if (!IsFreeport)
        {
            LostCharacters += character.IsBreak ? 0 : 1;
            return;
        }

        if (!character.IsBreak)
        {
            // Receive character interrupt: SMB2 holds the character, SM3.0 its parity error (seed 002 Tables C-3, C-4).
            _memory.SM[PortRegisters.ReceivedCharacter] = character.Value;
            var parity = _memory.SM[PortRegisters.ParityByte];
            _memory.SM[PortRegisters.ParityByte] = (byte)(character.Error ? parity | 1 : parity & ~1);
            raised.Add(new StlEvent(_registers.ReceiveCharacterEvent, character.At));
        }

        if (_receive is null)
        {
            LostCharacters += character.IsBreak ? 0 : 1;
            return;
        }

        if (_receive.Accept(character) is { } status)
        {
            EndReceive(status, character.At, raised);
        }
    }

    private void EndReceive(byte status, TimeSpan at, ICollection<StlEvent> raised)
    {
        _memory.SM[_registers.Status] = status;
        _receive = null;
        raised.Add(new StlEvent(_registers.ReceiveCompleteEvent, at));
    }
}
