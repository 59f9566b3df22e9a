namespace OperatorPanel.Stl;

/// <summary>The variable table a local belongs to; parameters of a CALL follow Input, InOut, Output in this order.</summary>
public enum AwlVariableSection
{
    /// <summary>VAR_INPUT.</summary>
    Input,

    /// <summary>VAR_IN_OUT.</summary>
    InOut,

    /// <summary>VAR_OUTPUT (subroutines only).</summary>
    Output,

    /// <summary>VAR (temporary).</summary>
    Temp,
}
