namespace OperatorPanel.Simulator.Stl.Freeport;

/// <summary>
/// One active RCV: the receive message function of seed 002 Table C-16. Start of message = idle line (the first
/// character after SMW90 ms without characters, counted from the RCV) and/or a break, followed by the start character
/// when sc = 1, or the start character alone; end of message = end character, timer, or SMB94 characters, and a
/// character with a parity (or framing) error ends it too. The start and end characters are stored and counted; buffer
/// byte 0 always holds the count so far (facts section 8). The inter-character and message timers run from the start
/// of the message (for il without sc that is the moment the idle time has passed, so "il=1, SMW90=0" plus a timer
/// is a no-response timeout); the inter-character timer restarts at every character.
/// </summary>
internal sealed class ReceiveMessage
{
    private readonly ReceiveSetup _setup;
    private readonly byte[] _v;
    private readonly int _buffer;
    private TimeSpan _idleFrom;
    private bool _breakSeen;
    private TimeSpan? _messageStart;
    private TimeSpan _lastCharacter;

    public ReceiveMessage(ReceiveSetup setup, byte[] v, int bufferOffset, TimeSpan at)
    {
        _setup = setup;
        _v = v;
        _buffer = bufferOffset;
        _idleFrom = at;
        _v[_buffer] = 0;
    }

    public int Count => _v[_buffer];

    /// <summary>When the timer ends this receive with status t if no character comes first; null without a timer.</summary>
    public TimeSpan? Deadline
    {
        get
        {
            if (!_setup.UseTimer)
            {
                return null;
            }

            if (_messageStart is { } start)
            {
                return (_setup.IsMessageTimer ? start : _lastCharacter) + _setup.Timeout;
            }

            // Idle line without a start character: the message starts as soon as the idle time has passed.
            return _setup.UseIdleLine && !_setup.UseStartCharacter ? _idleFrom + _setup.IdleTime + _setup.Timeout : null;
        }
    }

    /// <summary>Takes one character or break off the line; returns the SMB86 status when it ends the message.</summary>
    public byte? Accept(ReceivedCharacter character)
    {
        if (_messageStart is not null)
        {
            return character.Error ? ReceiveStatus.ParityError : Store(character);
        }

        if (character.IsBreak)
        {
            _breakSeen = _setup.UseBreak;
            _idleFrom = character.At;
            if (_breakSeen && !_setup.UseStartCharacter)
            {
                StartMessage(character.At);
            }

            return null;
        }

        var armed = (_setup.UseIdleLine && character.Start - _idleFrom >= _setup.IdleTime)
            || (_setup.UseBreak && _breakSeen)
            || (!_setup.UseIdleLine && !_setup.UseBreak);
        if (armed && !_setup.UseStartCharacter && character.Error)
        {
            // Without a start character the message began when the line was armed: the bad character ends it.
            StartMessage(_idleFrom + _setup.IdleTime);
            return ReceiveStatus.ParityError;
        }

        var wanted = !_setup.UseStartCharacter || character.Value == _setup.StartCharacter;
        if (!armed || !wanted || character.Error)
        {
            _idleFrom = character.At;
            _breakSeen = false;
            return null;
        }

        StartMessage(_setup.UseStartCharacter ? character.At : _idleFrom + _setup.IdleTime);
        return Store(character);
    }

    private void StartMessage(TimeSpan at)
    {
        _messageStart = at;
        _lastCharacter = at;
    }

    private byte? Store(ReceivedCharacter character)
    {
        var count = Count + 1;
        _v[_buffer + count] = character.Value;
        _v[_buffer] = (byte)count;
        _lastCharacter = character.At;
        if (_setup.UseEndCharacter && character.Value == _setup.EndCharacter && count > (_setup.UseStartCharacter ? 1 : 0))
        {
            return ReceiveStatus.EndCharacter;
        }

        return count >= _setup.MaxCount ? ReceiveStatus.MaxCount : null;
    }
}
