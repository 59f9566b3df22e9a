using CommunityToolkit.Mvvm.ComponentModel;
using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.ViewModels.Session;

/// <summary>
/// The one line at the bottom of the shell: the latest thing the operator should know (a write, a failure). Each
/// message replaces the one before (a success after an error clears the error) and expires: a success after
/// <see cref="InfoLifetime"/>, a failure after <see cref="ErrorLifetime"/>, so the line never shows an old state as
/// if it were now. A failure worth keeping stays where it happened (a write's row, a station's state) and in the log.
/// </summary>
public sealed partial class StatusLine : ObservableObject, IDisposable
{
    public const string IdleText = "Ready";

    /// <summary>Long enough to read a sentence twice.</summary>
    public static readonly TimeSpan InfoLifetime = TimeSpan.FromSeconds(10);

    /// <summary>A failure stays longer: the operator may have looked away when it came.</summary>
    public static readonly TimeSpan ErrorLifetime = TimeSpan.FromSeconds(60);

    private readonly TimeProvider _time;
    private readonly IUiDispatcher? _dispatcher;
    private ITimer? _expiry;
    private long _shown;

    /// <param name="time">The clock of the expiry.</param>
    /// <param name="dispatcher">Where the expiry clears the line (the UI thread); null: on the timer's thread.</param>
    public StatusLine(TimeProvider? time = null, IUiDispatcher? dispatcher = null)
    {
        _time = time ?? TimeProvider.System;
        _dispatcher = dispatcher;
    }

    [ObservableProperty]
    public partial string Text { get; private set; } = IdleText;

    /// <summary>The message is a failure (red); never set for a success.</summary>
    [ObservableProperty]
    public partial bool IsError { get; private set; }

    public void Show(string text) => Set(text, isError: false, InfoLifetime);

    public void ShowError(string text) => Set(text, isError: true, ErrorLifetime);

    public void Dispose() => _expiry?.Dispose();

    private void Set(string text, bool isError, TimeSpan lifetime)
    {
        ArgumentNullException.ThrowIfNull(text);
        (Text, IsError) = (text, isError);
        var shown = Interlocked.Increment(ref _shown);
        _expiry?.Dispose();
        _expiry = _time.CreateTimer(_ => Expire(shown), null, lifetime, Timeout.InfiniteTimeSpan);
    }

    private void Expire(long shown)
    {
        void Clear()
        {
            // Only the message this timer was set for: a newer one has its own.
            if (Interlocked.Read(ref _shown) == shown)
            {
                (Text, IsError) = (IdleText, false);
            }
        }

        if (_dispatcher is { } dispatcher)
        {
            dispatcher.Post(Clear);
        }
        else
        {
            Clear();
        }
    }
}
